"""Job files, module by module: :mod:`~dispkin.job.reader` reads the YAML with each key's line
and column, :mod:`~dispkin.job.schema` validates it against ``job.schema.json``,
:mod:`~dispkin.job.builder` builds it into the :mod:`~dispkin.job.model` (a :class:`Job`),
:mod:`~dispkin.job.planning` plans it (applying its stops, resumptions and speed overrides,
:mod:`~dispkin.job.events`), :mod:`~dispkin.job.sampling` samples the trajectory
into joints and poses, :mod:`~dispkin.job.summary` tells which limit binds and
:mod:`~dispkin.job.export` writes CSV and JSON.

:mod:`dispkin.jobs` gathers the public names of all of them in one place.
"""
