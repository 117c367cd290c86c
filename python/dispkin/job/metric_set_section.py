"""The metric set of a job (``metric_set``): its points, lists or shapes, the group speeds and a
hexapod's leg group, each error at its key. A section of the job builder (:mod:`.builder`),
whose ``fail`` and ``call`` it uses."""

from typing import Any, Dict, List

from .. import shapes
from .._core import MetricSet
from .model import KeyPath

#: The keys of a metric_set.points entry that only a `shape` entry uses.
_SHAPE_PARAMETERS = ("center", "centre", "radius", "size", "subdivisions", "count", "circumscribed")

#: Per shape, the shape parameters it does not take (the schema allows all of them on every shape).
_NOT_PARAMETERS_OF = {
    "icosahedron": ("size", "subdivisions", "count"),
    "icosphere": ("size", "count", "circumscribed"),
    "box": ("radius", "subdivisions", "count", "circumscribed"),
    "sphere": ("size", "subdivisions", "count", "circumscribed"),
    "spherical_shell": ("size", "subdivisions", "circumscribed"),
}


class MetricSetSection:
    """The metric_set section of the job builder."""

    data: Dict[str, Any]
    fail: Any
    call: Any

    def metric_set(self, job: Dict[str, Any]) -> MetricSet:
        """metric_set: its points, lists or shapes, the group speeds, and a hexapod's leg group."""
        m = self.data["metric_set"]
        metric_set = MetricSet()
        for i, entry in enumerate(m.get("points", [])):
            self.points(metric_set, entry, ("metric_set", "points", i))
        self.group_speeds(metric_set, m.get("groups", []))
        self.leg_speed_group(job, metric_set)
        if metric_set.point_count == 0 and metric_set.sphere_count == 0:
            raise self.fail(
                ("metric_set",), "the metric set has no points: give metric_set.points (or a hexapod leg_speed_group)"
            )
        self.call(("metric_set",), metric_set.require_well_formed)
        return metric_set

    def points(self, metric_set: MetricSet, entry: Dict[str, Any], at: KeyPath) -> None:
        """One metric_set.points entry: a list of relative or absolute points, or a shape."""
        group = entry.get("group", 0)
        if "shape" not in entry:  # the schema allows the shape keys everywhere; only shapes use them
            for key in _SHAPE_PARAMETERS:
                if key in entry:
                    raise self.fail(at + (key,), "a parameter of shapes only, not of a list of points")
        if "relative" in entry:
            self.call(at + ("relative",), metric_set.add_relative, entry["relative"], group)
        elif "absolute" in entry and "shape" not in entry:
            self.call(at + ("absolute",), metric_set.add_absolute, entry["absolute"], group)
        else:
            self.shape(metric_set, entry, at, group)

    def shape(self, metric_set: MetricSet, entry: Dict[str, Any], at: KeyPath, group: int) -> None:
        """A shape entry: an exact sphere, or the points of an icosahedron, icosphere, box or
        spherical shell (relative unless `absolute: true`)."""
        kind = entry["shape"]
        # `center` as the API spells it; `centre`, the spelling of earlier job files, still reads.
        if "center" in entry and "centre" in entry:
            raise self.fail(at + ("centre",), "`centre` is an alias of `center`: give one of them, not both")
        center = entry.get("center", entry.get("centre", (0.0, 0.0, 0.0)))
        absolute = bool(entry.get("absolute", False))
        for key in _NOT_PARAMETERS_OF[kind]:
            if key in entry:
                raise self.fail(at + (key,), f"not a parameter of shape {kind!r}")
        if kind == "sphere":
            self.call(at, metric_set.add_sphere, center, entry["radius"], absolute, group)
            return
        if kind == "icosahedron":
            points = self.call(at, shapes.icosahedron, entry["radius"], center, entry.get("circumscribed", True))
        elif kind == "icosphere":
            points = self.call(at, shapes.icosphere, entry["radius"], entry["subdivisions"], center)
        elif kind == "box":
            points = self.call(at, shapes.box, entry["size"], center)
        else:
            points = self.call(at, shapes.spherical_shell, entry["radius"], entry["count"], center)
        add = metric_set.add_absolute if absolute else metric_set.add_relative
        self.call(at, add, points, group)

    def group_speeds(self, metric_set: MetricSet, groups: List[Dict[str, Any]]) -> None:
        """metric_set.groups: a speed limit of its own for a group that has points."""
        populated = set(metric_set.groups)  # set_group_speed adds the group even without points
        groups_seen = set()
        for i, g in enumerate(groups):
            if g["group"] not in populated:
                raise self.fail(("metric_set", "groups", i, "group"), f"{g['group']}: no points belong to this group")
            if g["group"] in groups_seen:
                raise self.fail(("metric_set", "groups", i, "group"), f"{g['group']}: group given twice")
            groups_seen.add(g["group"])
            self.call(("metric_set", "groups", i), metric_set.set_group_speed, g["group"], g["speed"])

    def leg_speed_group(self, job: Dict[str, Any], metric_set: MetricSet) -> None:
        """machine.hexapod.leg_speed_group (rule (a)): the upper leg joints as a group of their
        own, held to the leg speed."""
        hexapod = job.get("hexapod")
        leg_group = (self.data.get("machine") or {}).get("hexapod", {}).get("leg_speed_group")
        if hexapod is None or leg_group is None:
            return
        at: KeyPath = ("machine", "hexapod", "leg_speed_group")
        if leg_group in metric_set.groups:
            raise self.fail(
                at, f"{leg_group}: the metric set already has group {leg_group}; the legs need a group of their own"
            )
        self.call(at, hexapod.add_leg_speed_group, metric_set, leg_group)
        job["leg_speed_group"] = leg_group
