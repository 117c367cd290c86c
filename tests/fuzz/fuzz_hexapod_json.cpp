// libFuzzer target: the hexapod description loader, Hexapod::from_json.
//
// Input: JSON text. A loaded hexapod must give finite leg lengths at its home pose and must
// write a description that loads again.
#include <cstddef>
#include <cstdint>
#include <string>

#include <dispkin/hexapod/hexapod.hpp>

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  dispkin::fuzz::expect_clean([&] {
    const dispkin::hexapod::Hexapod hexapod = dispkin::hexapod::Hexapod::from_json(text);
    dispkin::fuzz::check_finite(hexapod.leg_lengths(hexapod.home()), "leg_lengths(home) of a loaded hexapod");
    // What was accepted once must be accepted again after a round trip.
    try {
      (void)dispkin::hexapod::Hexapod::from_json(hexapod.to_json());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "round trip refused: %s\n", e.what());
      dispkin::fuzz::finding("to_json() of a loaded hexapod does not load");
    }
  });
  return 0;
}
