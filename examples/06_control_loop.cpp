// 06 — dispkin in a controller's loop: a simulated 1 kHz cycle samples a MotionStream while a
// worker thread plans the requests (moves streamed in, a feed hold, a resumption, a speed
// override) and hands each new stream over; the cycle swaps it in at its start and never
// allocates, locks or waits for planning (doc/events.md §5 and §6).
//
// The hand-over: the worker copies the stream, applies a request to the copy (planning,
// allocating) and publishes it with an atomic store of a shared pointer; the cycle loads it once
// per cycle. The cycle only reads an immutable stream, so sampling needs no lock, and the worker
// keeps every stream it replaced until the cycle has let go of it, so that no stream is freed in
// the cycle. (The shared pointer's atomic load is the cycle's one synchronisation; libstdc++
// guards it with a short spin lock — a controller that must not spin hands over through a
// lock-free triple buffer instead. The Python twin is 06_control_loop.py.)
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include <dispkin/dispkin.hpp>
#include <dispkin/planning/motion_stream.hpp>

using namespace dispkin;
using V = Eigen::Vector3d;

namespace {

// A zig-zag of LIN moves of 8 cm, the tool turning 4° about z per move.
std::vector<Path> program(int count) {
  std::vector<Path> moves;
  Posed p;
  for (int k = 1; k <= count; ++k) {
    const Posed q(Eigen::Quaterniond(Eigen::AngleAxisd(4.0 * k * M_PI / 180.0, V::UnitZ())),
                  V(0.08 * k, 0.03 * (k % 2), 0.0));
    moves.push_back(Path::lin(p, q));
    p = q;
  }
  return moves;
}

// Requests from the cycle to the worker: each applied to a copy of the latest stream.
class Worker {
 public:
  explicit Worker(std::shared_ptr<const MotionStream> first) : latest_(std::move(first)), thread_([this] { run(); }) {}
  ~Worker() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      quit_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  // Called from the cycle: queues a request (a short critical section; in a hard real-time
  // controller a lock-free queue takes its place).
  void request(std::function<void(MotionStream&)> change) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      requests_.push_back(std::move(change));
    }
    wake_.notify_one();
  }
  // The stream the cycle samples.
  std::shared_ptr<const MotionStream> latest() const { return std::atomic_load(&latest_); }
  bool idle() {
    std::lock_guard<std::mutex> lock(mutex_);
    return requests_.empty() && !busy_;
  }

 private:
  void run() {
    for (;;) {
      std::function<void(MotionStream&)> change;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [this] { return quit_ || !requests_.empty(); });
        if (quit_) return;
        change = std::move(requests_.front());
        requests_.pop_front();
        busy_ = true;
      }
      std::shared_ptr<const MotionStream> previous = std::atomic_load(&latest_);
      auto next = std::make_shared<MotionStream>(*previous);
      change(*next);
      std::atomic_store(&latest_, std::shared_ptr<const MotionStream>(std::move(next)));
      // Freed here once the cycle no longer holds them, never in the cycle.
      retired_.push_back(std::move(previous));
      retired_.erase(std::remove_if(retired_.begin(), retired_.end(), [](const auto& s) { return s.use_count() == 1; }),
                     retired_.end());
      std::lock_guard<std::mutex> lock(mutex_);
      busy_ = false;
    }
  }

  std::shared_ptr<const MotionStream> latest_;
  std::vector<std::shared_ptr<const MotionStream>> retired_;  // the worker's only
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void(MotionStream&)>> requests_;
  bool quit_ = false, busy_ = false;
  std::thread thread_;
};

}  // namespace

int main() {
  MetricSetd tool;
  tool.add_relative(shapes::icosahedron(0.02, V(0, 0, 0)));    // around the flange
  tool.add_relative(shapes::icosahedron(0.02, V(0, 0, 0.2)));  // around the tool tip
  const Limits limits{0.2, 1.0, 10.0};
  std::deque<Path> moves;
  for (Path& move : program(12)) moves.push_back(std::move(move));

  MotionStream start(tool, limits, ProfileKind::scurve, 0.002);
  start.append(moves.front(), 0.0);
  moves.pop_front();
  Worker worker(std::make_shared<const MotionStream>(std::move(start)));

  // The cycle: 1 ms of simulated time per cycle (run as fast as the machine goes). Events: a
  // feed hold at 1.5 s, resumed at 2.5 s, an override of 50 % at 3.5 s.
  const double dt = 1e-3;
  bool held = false, resumed = false, slowed = false;
  double fastest = 0.0, longest_cycle = 0.0;
  double t = 0.0, stop_time = 0.0, stopped_speed = 1.0;
  Posed last_pose;
  double largest_step = 0.0;
  MotionStream::Cursor cursor;
  std::shared_ptr<const MotionStream> stream = worker.latest();
  for (int cycle = 0; cycle < 20000; ++cycle, t += dt) {
    const auto begin = std::chrono::steady_clock::now();
    // At the start of a cycle: the newest stream (requests made at t apply from t on, so the
    // samples of earlier cycles are the same in it).
    std::shared_ptr<const MotionStream> newest = worker.latest();
    if (newest != stream) stream = std::move(newest);
    const TrajectorySample x = stream->sample(t, cursor);
    const auto end = std::chrono::steady_clock::now();
    longest_cycle = std::max(longest_cycle, std::chrono::duration<double>(end - begin).count());
    if (cycle > 0) largest_step = std::max(largest_step, (x.pose.translation() - last_pose.translation()).norm());
    last_pose = x.pose;
    fastest = std::max(fastest, x.s_dot);

    // Requests. A move is streamed in while about two moves are planned ahead (the stream joins
    // a move that comes while the motion runs, planning only the path ahead of it).
    const double planned_ahead = stream->duration() - t;
    if (!moves.empty() && planned_ahead < 1.0 && worker.idle()) {
      const Path move = moves.front();
      moves.pop_front();
      const double at = t;
      worker.request([move, at](MotionStream& s) { s.append(move, at); });
    }
    if (!held && t >= 1.5) {
      held = true;
      stop_time = t;
      worker.request([at = t](MotionStream& s) { s.stop(at); });
    }
    if (held && !resumed && t >= 2.4 && t < 2.5) stopped_speed = std::min(stopped_speed, x.s_dot);
    if (held && !resumed && t >= 2.5) {
      resumed = true;
      worker.request([at = t](MotionStream& s) { s.resume(at); });
    }
    if (!slowed && t >= 3.5) {
      slowed = true;
      worker.request([at = t](MotionStream& s) { s.set_override(at, 0.5); });
    }
    // Let the simulated worker keep up with simulated time: a real one runs alongside.
    while (!worker.idle()) std::this_thread::yield();
    if (moves.empty() && resumed && slowed && stream->done(t) && worker.latest() == stream) break;
  }

  const Posed goal = program(12).back().end();
  std::printf("ran %.3f s of motion in 1 kHz cycles; feed hold at %.3f s (speed %.2g m/s before resuming)\n", t,
              stop_time, stopped_speed);
  std::printf("path speed at most %.4f m/s (limit %.2f); largest step of the tool between cycles %.3g m\n", fastest,
              limits.velocity, largest_step);
  std::printf("longest cycle (load and sample) %.1f us; legs %zu; ends at the last pose: %s\n", longest_cycle * 1e6,
              stream->leg_count(), stream->sample(stream->duration()).pose.is_approx(goal, 1e-9) ? "yes" : "no");
  const bool ok = fastest <= limits.velocity * (1 + 1e-9) && stopped_speed < 1e-9 && largest_step < 0.2 * 2e-3 &&
                  stream->sample(stream->duration()).pose.is_approx(goal, 1e-9);
  return ok ? 0 : 1;
}
