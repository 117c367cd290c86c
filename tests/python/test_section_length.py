"""Section lengths (doc/section-length.md §2–3) against dense finite-difference sampling of the
actual motion.

For screw and decoupled (LIN) sections of random sets (relative and absolute points, a relative
and an absolute ball) the poses come from dispkin.interpolate, and the speed per unit τ of every
object is measured by finite differences: points from their positions (relative: T(τ) r,
absolute: T(τ)⁻¹ a), balls by sphere_speed of the finite-difference body twist T⁻¹ dT/dτ. The
largest sampled speed (a 201-point grid in τ, its three best local maxima refined by golden-
section search) must never exceed section_length (up to 1e-9 relative, the finite-difference
error) and must come within 1e-6 of it (the length is exact, not only a bound).
"""

import math

import numpy as np
import pytest

import dispkin
from _helpers import COUNT, NORMS, SetSpec, hat, random_pose, relative_motion, rng_for

# Each case runs ~1000 interpolate() calls in a Python loop (~5 ms), so this oracle takes
# min(COUNT, 800) cases per interpolation.
CASES = min(COUNT, 800)
GRID = 200
H = 1e-3  # step of the 5-point derivative: truncation ~H⁴θ⁵/30, rounding ~1e-16/H, both < 1e-11
GOLDEN_STEPS = 34  # bracket 2/GRID shrinks to ~1e-9
FD_ERROR = 1e-9
EXACT = 1e-6
MOTIONS = ["generic", "generic", "translation", "rotation", "near_pi"]


def random_section_set(rng):
    spec = SetSpec(
        relative=rng.normal(scale=0.3, size=(3, 3)),
        absolute=rng.uniform(-1.0, 1.0, size=(2, 3)),
        relative_spheres=[(rng.normal(scale=0.3, size=3), rng.uniform(0.0, 0.3))],
        absolute_spheres=[(rng.uniform(-1.0, 1.0, 3), rng.uniform(0.0, 0.3))],
    )
    return spec


class Section:
    """Speeds of a set's objects along dispkin.interpolate(a, b, τ, kind, pivot)."""

    def __init__(self, spec, a, b, kind, pivot):
        self.spec, self.a, self.b, self.kind, self.pivot = spec, a, b, kind, pivot

    def matrices(self, taus):
        return np.array([dispkin.interpolate(self.a, self.b, t, self.kind, self.pivot).matrix() for t in taus])

    def speeds(self, m, dm):
        """Largest speed per unit τ over the set, for poses m (n, 4, 4) and derivatives dm."""
        r, t, dr, dt = m[:, :3, :3], m[:, :3, 3], dm[:, :3, :3], dm[:, :3, 3]
        rt = np.transpose(r, (0, 2, 1))
        spec = self.spec
        # relative point p: d/dτ (R p + t)
        rel = np.linalg.norm(np.einsum("nij,kj->nki", dr, spec.relative) + dt[:, None, :], axis=2).max(
            axis=1, initial=0.0
        )
        # absolute point x: d/dτ Rᵀ (x − t) = dRᵀ (x − t) − Rᵀ dt
        rel_x = spec.absolute[None, :, :] - t[:, None, :]
        absolute = np.einsum("nji,nkj->nki", dr, rel_x) - np.einsum("nij,nj->ni", rt, dt)[:, None, :]
        best = np.maximum(rel, np.linalg.norm(absolute, axis=2).max(axis=1, initial=0.0))
        # balls: sphere_speed of the body twist (v, ω) = (Rᵀ dt, vee(Rᵀ dR))
        w_hat = rt @ dr
        omega = 0.5 * np.stack(
            [w_hat[:, 2, 1] - w_hat[:, 1, 2], w_hat[:, 0, 2] - w_hat[:, 2, 0], w_hat[:, 1, 0] - w_hat[:, 0, 1]], axis=1
        )
        twists = np.hstack([np.einsum("nij,nj->ni", rt, dt), omega])
        for n, xi in enumerate(twists):
            for c, radius in spec.relative_spheres:
                best[n] = max(best[n], dispkin.sphere_speed(xi, c, radius))
            for c, radius in spec.absolute_spheres:
                best[n] = max(best[n], dispkin.sphere_speed(xi, rt[n] @ (c - t[n]), radius))
        return best

    def accurate(self, taus):
        """Speeds at `taus` with the 5-point derivative (the motion formulas are analytic in τ,
        so the stencil may reach past the ends of [0, 1])."""
        taus = np.asarray(taus, dtype=float)
        offsets = np.array([0.0, -2 * H, -H, H, 2 * H])
        m = self.matrices((taus[:, None] + offsets).ravel()).reshape(len(taus), 5, 4, 4)
        dm = (m[:, 1] - 8 * m[:, 2] + 8 * m[:, 3] - m[:, 4]) / (12 * H)
        return self.speeds(m[:, 0], dm)

    def sampled_maximum(self):
        """The largest accurate speed found: grid, then golden-section refinement of the three
        best local maxima of the grid, plus both ends exactly."""
        grid = np.linspace(-1.0 / GRID, 1.0 + 1.0 / GRID, GRID + 3)
        m = self.matrices(grid)
        coarse = self.speeds(m[1:-1], (m[2:] - m[:-2]) * (GRID / 2.0))  # for ranking only
        padded = np.concatenate(([-np.inf], coarse, [-np.inf]))
        peaks = [k for k in range(GRID + 1) if padded[k + 1] >= padded[k] and padded[k + 1] >= padded[k + 2]]
        peaks = sorted(peaks, key=lambda k: -coarse[k])[:3]
        lo = np.array([max(0.0, (k - 1) / GRID) for k in peaks])
        hi = np.array([min(1.0, (k + 1) / GRID) for k in peaks])
        best = self.accurate([0.0, 1.0]).max()
        g = (math.sqrt(5.0) - 1.0) / 2.0
        c, d = hi - g * (hi - lo), lo + g * (hi - lo)
        fc, fd = self.accurate(c), self.accurate(d)
        for _ in range(GOLDEN_STEPS):
            best = max(best, fc.max(), fd.max())
            left = fc > fd  # the maximum is in [lo, d]
            hi = np.where(left, d, hi)
            lo = np.where(left, lo, c)
            new_c, new_d = hi - g * (hi - lo), lo + g * (hi - lo)
            probe = np.where(left, new_c, new_d)
            fp = self.accurate(probe)
            c, d, fc, fd = (
                np.where(left, new_c, d),
                np.where(left, c, new_d),
                np.where(left, fp, fd),
                np.where(left, fc, fp),
            )
        return max(best, fc.max(), fd.max())


@pytest.mark.parametrize("kind", ["screw", "decoupled"])
def test_section_length_is_the_largest_sampled_speed(kind):
    rng = rng_for("section-" + kind)
    ratios = np.empty(CASES)
    for i in range(CASES):
        spec = random_section_set(rng)
        s = spec.build()
        a = random_pose(rng)
        b = a * relative_motion(rng, MOTIONS[i % len(MOTIONS)])
        pivot = rng.uniform(-0.3, 0.3, 3)
        length = dispkin.section_length(s, a, b, interpolation=kind, pivot=pivot)
        sampled = Section(spec, a, b, kind, pivot).sampled_maximum()
        ratios[i] = length / sampled
        assert length >= sampled * (1 - FD_ERROR), (i, kind, a, b, pivot, spec, length, sampled)
        assert length <= sampled * (1 + EXACT), (i, kind, a, b, pivot, spec, length, sampled)
        # A chord is never longer than the arc: d(a, b) <= L (doc/section-length.md eq. 2).
        assert dispkin.disp_distance(s, a, b) <= length * (1 + 1e-12)
        if kind == "screw":  # a screw section does not depend on the pivot
            assert dispkin.section_length(s, a, b, interpolation="screw") == length


def test_decoupled_section_of_a_ball_centred_on_the_pivot_has_the_closed_form():
    # doc/section-length.md eq. 8: sqrt(Δc∥² + (‖Δc⊥‖ + θρ)²), exact for a ball centred on the
    # rotation axis through the pivot (Δc the pivot's travel in world, θ the angle, ∥ along the
    # world axis).
    rng = rng_for("section-ball-at-pivot")
    for i in range(COUNT):
        a = random_pose(rng)
        b = a * relative_motion(rng, ["generic", "translation", "rotation", "tiny", "near_pi"][i % 5])
        pivot, radius = rng.uniform(-0.3, 0.3, 3), rng.uniform(0.0, 0.3)
        s = dispkin.MetricSet()
        s.add_sphere(pivot, radius)
        delta_c = b.transform(pivot) - a.transform(pivot)
        rotation_vector = a.rotation() @ (a.inverse() * b).log()[3:]  # world axis times θ
        theta = np.linalg.norm(rotation_vector)
        axis = rotation_vector / theta if theta > 0 else np.zeros(3)
        along = delta_c @ axis
        across = np.linalg.norm(delta_c - along * axis)
        expected = math.hypot(along, across + theta * radius)
        got = dispkin.section_length(s, a, b, interpolation="decoupled", pivot=pivot)
        assert abs(got - expected) <= 1e-12 * expected + 1e-15, (i, got, expected)


def test_screw_section_speeds_are_constant_and_equal_to_the_twist_speed():
    # A screw motion has a constant body twist ξ = log(a⁻¹ b): L = max_point_speed(set, a, ξ).
    rng = rng_for("section-screw-twist")
    for i in range(min(COUNT, 2000)):
        spec = random_section_set(rng)
        s = spec.build()
        a = random_pose(rng)
        b = a * relative_motion(rng, MOTIONS[i % len(MOTIONS)])
        xi = (a.inverse() * b).log()
        speed = dispkin.max_point_speed(s, a, xi)
        assert speed == pytest.approx(dispkin.section_length(s, a, b, "screw"), rel=1e-14)
        # Independent of the pose along the section (absolute objects included).
        mid = dispkin.interpolate(a, b, 0.37, "screw")
        assert dispkin.max_point_speed(s, mid, xi) == pytest.approx(speed, rel=1e-12)
        # Relative points alone: max ‖v + ω × r‖ in numpy.
        rel = np.linalg.norm(xi[:3] + spec.relative @ hat(xi[3:]).T, axis=1).max()
        only_rel = dispkin.MetricSet()
        only_rel.add_relative(spec.relative)
        assert dispkin.max_point_speed(only_rel, a, xi) == pytest.approx(rel, rel=1e-14)


@pytest.mark.parametrize("kind", ["screw", "decoupled"])
def test_group_weights_scale_section_lengths(kind):
    rng = rng_for("section-groups-" + kind)
    for _ in range(200):
        first, second = random_section_set(rng), random_section_set(rng)
        both = first.build()
        both.add_absolute(second.absolute, group=1)
        for c, r in second.relative_spheres:
            both.add_sphere(c, r, group=1)
        both.set_group_speed(1, v1 := rng.uniform(0.01, 1.0))
        only_second = SetSpec(absolute=second.absolute, relative_spheres=second.relative_spheres).build()
        v_sys = rng.uniform(0.01, 1.0)
        a, b, pivot = random_pose(rng), random_pose(rng), rng.uniform(-0.3, 0.3, 3)
        expected = max(
            dispkin.section_length(first.build(), a, b, kind, pivot),
            dispkin.section_length(only_second, a, b, kind, pivot) * v_sys / v1,
        )
        got = dispkin.section_length(both, a, b, kind, pivot, system_velocity=v_sys)
        assert got == pytest.approx(expected, rel=1e-15)
    assert set(NORMS) == {"euclidean", "max", "l1"}
