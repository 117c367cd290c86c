"""Robot descriptions shipped with dispkin, so that the examples and the README run from an
installed package.

``ur5e.urdf``
    A Universal Robots UR5e written from its published DH table (joint limits, link masses and
    inertias, joint speeds and torques of the datasheet); base link ``base_link``, tip link
    ``tool0``.

``iiwa14.urdf``
    A seven-joint SRS arm with the published kinematics of the KUKA LBR iiwa 14 R820 (its DH
    table, joint limits, speeds and torques); the masses and inertias are round figures, not
    KUKA's. Family ``locked_joint``: its redundancy is the seventh joint (``arm.redundancy``).
    Base link ``link_0``, tip link ``tool0``.

Both are written by the dispkin authors from the manufacturers' published figures and ship under
dispkin's own licence (BSD-3-Clause).

Example::

    import dispkin
    arm = dispkin.SerialArm.from_urdf(dispkin.data.path("ur5e.urdf"), "base_link", "tool0")
    iiwa = dispkin.SerialArm.from_urdf(dispkin.data.path("iiwa14.urdf"), "link_0", "tool0")
"""

from __future__ import annotations

from importlib import resources


def names() -> list[str]:
    """The names of the shipped files (what :func:`path` accepts), sorted."""
    return sorted(
        entry.name
        for entry in resources.files(__name__).iterdir()
        if entry.is_file() and not entry.name.endswith((".py", ".pyc"))
    )


def path(name: str) -> str:
    """The path of the shipped file ``name`` (one of :func:`names`) on this machine.

    Raises ValueError naming ``name`` and the files there are when there is no such file.
    """
    available = names()
    if name not in available:
        raise ValueError(f"dispkin.data.path: name = {name!r} is not a shipped file; there are {available}")
    return str(resources.files(__name__).joinpath(name))
