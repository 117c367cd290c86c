"""Batches of jobs: ``dispkin batch JOB... -o DIR`` and :func:`batch` plan many job files at once,
on a pool of local processes or on a Dask distributed cluster, each exactly as ``dispkin plan``
plans it alone (:func:`dispkin.commands.plan_to_files`, into a folder of DIR named after the job
file), and write one table, ``DIR/batch_summary.csv``, of every job's duration, binding limit and
broken machine limits. A job that fails is reported with its error; the others go on.

On a cluster, the workers read the job files (and the files they name) and write into DIR at
the paths the client gives them: absolute paths on a file system that every worker shares.
"""

import csv
import dataclasses
import io
import os
import pathlib
import sys
from typing import Any, Callable, Dict, Iterable, Iterator, List, Optional, Sequence, TextIO, Tuple, Union

from .job.model import JobError
from .progress import Progress

#: The summary table of a batch, in its output directory.
SUMMARY_FILE = "batch_summary.csv"

#: Columns of the summary table: the job file, its folder in DIR, the outcome (planned, limits
#: broken, failed), the trajectory's duration (s), the binding limit, how many machine limits
#: the trajectory breaks and which, and the error of a failed job.
SUMMARY_COLUMNS = ("job", "folder", "status", "duration", "binding", "violations", "broken_limits", "error")

#: Most local worker processes: each one holds a Python interpreter with the library (tens of MB)
#: and more processes than cores only queue for them.
MAX_WORKERS = max(64, 2 * (os.cpu_count() or 1))

#: Outcomes of a job in the summary table.
PLANNED, LIMITS_BROKEN, FAILED = "planned", "limits broken", "failed"


@dataclasses.dataclass
class BatchResult:
    """One job of a batch: where its files are, and what planning it gave."""

    #: The job file as given.
    job: str
    #: Its output folder (DIR/folder).
    outdir: pathlib.Path
    #: PLANNED, LIMITS_BROKEN (the files are written; see `violations`) or FAILED (see `error`).
    status: str
    #: The trajectory's duration (s); None for a failed job.
    duration: Optional[float] = None
    #: The limit the trajectory runs at (the summary's "binding limit").
    binding: str = ""
    #: Each machine limit the trajectory breaks, described on one line.
    violations: List[str] = dataclasses.field(default_factory=list)
    #: Why the job failed (its JobError, or the error of the worker that planned it).
    error: str = ""
    #: The files written.
    written: List[pathlib.Path] = dataclasses.field(default_factory=list)

    def row(self) -> Dict[str, str]:
        """The job's row of the summary table."""
        return {
            "job": self.job,
            "folder": self.outdir.name,
            "status": self.status,
            "duration": "" if self.duration is None else repr(self.duration),
            "binding": self.binding,
            "violations": str(len(self.violations)) if self.status != FAILED else "",
            "broken_limits": "; ".join(self.violations),
            "error": self.error,
        }


def plan_job_file(job_file: str, outdir: str, plot: bool = False) -> Dict[str, Any]:
    """Plan one job of a batch where this runs (a worker): what `dispkin plan JOB -o OUTDIR`
    does, its outcome as plain data. Any error is the job's, never the batch's."""
    from .commands import plan_to_files

    try:
        planned = plan_to_files(job_file, outdir, plot)
    except JobError as error:
        return {"error": str(error)}
    except Exception as error:  # noqa: BLE001 - one job's failure, whatever it is, must not stop the others
        return {"error": f"{type(error).__name__}: {error}"}
    return {
        "duration": float(planned.summary["duration"]),
        "binding": planned.summary["binding"],
        "violations": planned.violations,
        "written": [str(p) for p in planned.written],
    }


def job_folders(jobs: Sequence[str]) -> List[str]:
    """The output folder of each job in the batch's directory: the job file's name without
    ``.yaml``; a name given to an earlier job (or the summary table's) gets ``-2``, ``-3``..."""
    taken = {SUMMARY_FILE}
    folders = []
    for job in jobs:
        stem = pathlib.Path(job).stem
        stem = "job" if stem in ("", ".", "..") else stem  # never a folder outside DIR
        name, n = stem, 1
        while name in taken:
            n += 1
            name = f"{stem}-{n}"
        taken.add(name)
        folders.append(name)
    return folders


def batch(
    jobs: Iterable[Union[str, os.PathLike]],
    outdir: Union[str, os.PathLike],
    workers: Optional[int] = None,
    scheduler: Any = None,
    plot: bool = False,
    progress: Optional[Progress] = None,
) -> List[BatchResult]:
    """Plan every job file of `jobs`, each into its own folder of `outdir` exactly as
    ``dispkin plan JOB -o OUTDIR/FOLDER`` plans it, and write ``OUTDIR/batch_summary.csv`` (one
    row per job, in the order given). The jobs run on `workers` local processes (default: one
    per core), or on the Dask cluster of `scheduler` (its address, e.g. ``tcp://host:8786``, or a
    ``distributed.Client``; needs ``pip install 'dispkin[distributed]'``). Returns one
    :class:`BatchResult` per job, in the order given; a failed job is one with status FAILED.
    Bad arguments raise a JobError naming the argument and its value."""
    job_files = [os.fspath(job) for job in jobs]
    if not job_files:
        raise JobError("jobs: no job file given")
    if plot:
        from .commands import require_matplotlib

        require_matplotlib()  # before the work, not in every job
    if scheduler is not None and workers is not None:
        raise JobError(
            f"workers = {workers!r}: give either workers (local processes) or scheduler (a Dask cluster), not both"
        )
    run = (
        _run_on_cluster(scheduler)
        if scheduler is not None
        else _run_on_processes(_worker_count(workers, len(job_files)))
    )
    directory = _output_directory(outdir)
    progress = progress or Progress(None, "")
    folders = [directory / name for name in job_folders(job_files)]
    # Absolute paths: a worker does not run in this directory (nor, on a cluster, on this machine).
    tasks = [
        (str(pathlib.Path(job).absolute()), str(folder.absolute()), plot) for job, folder in zip(job_files, folders)
    ]
    results: List[Optional[BatchResult]] = [None] * len(tasks)
    for done, (index, outcome) in enumerate(run(tasks), start=1):
        results[index] = _result(job_files[index], folders[index], tasks[index], outcome)
        _report(progress, results[index], done, len(tasks))
    _write_summary(directory, results)
    return results


def _output_directory(outdir: Union[str, os.PathLike]) -> pathlib.Path:
    """OUTDIR, made if missing; a JobError when it cannot be a directory."""
    directory = pathlib.Path(outdir)
    if os.path.lexists(directory) and not directory.is_dir():
        raise JobError(f"-o DIR = {str(outdir)!r}: is not a directory")
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise JobError(f"-o DIR = {str(outdir)!r}: cannot be made: {error.strerror or error}") from error
    return directory


def _worker_count(workers: Optional[int], jobs: int) -> int:
    """The number of local processes: `workers` (1 to MAX_WORKERS), or one per core; never more
    than there are jobs."""
    if workers is None:
        workers = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    elif isinstance(workers, bool) or not isinstance(workers, int) or not 1 <= workers <= MAX_WORKERS:
        raise JobError(f"workers = {workers!r}: must be an integer from 1 to {MAX_WORKERS}")
    return min(workers, jobs)


Task = Tuple[str, str, bool]
Runner = Callable[[List[Task]], Iterator[Tuple[int, Dict[str, Any]]]]


def _run_on_processes(workers: int, plan: Callable[..., Dict[str, Any]] = plan_job_file) -> Runner:
    """Runs the tasks on a pool of `workers` fresh Python processes (spawned: nothing of this
    process's threads or state is inherited), yielding (index, outcome) as jobs finish. A process
    that dies (killed for its memory, a crash) breaks the pool and every job it still held: those
    jobs run again, each in a process of its own, so that only the job that kills its process
    fails, and says so."""

    def run(tasks: List[Task]) -> Iterator[Tuple[int, Dict[str, Any]]]:
        import concurrent.futures.process

        lost: List[int] = []
        with _process_pool(workers) as pool:
            futures = {pool.submit(plan, *task): i for i, task in enumerate(tasks)}
            for future in concurrent.futures.as_completed(futures):
                if isinstance(future.exception(), concurrent.futures.process.BrokenProcessPool):
                    lost.append(futures[future])
                else:
                    yield futures[future], _outcome(future)
        for i in sorted(lost):
            with _process_pool(1) as alone:
                future = alone.submit(plan, *tasks[i])
                if isinstance(future.exception(), concurrent.futures.process.BrokenProcessPool):
                    yield i, {"error": "the worker process planning it died: killed (out of memory?) or crashed"}
                else:
                    yield i, _outcome(future)

    return run


def _process_pool(workers: int) -> Any:
    import concurrent.futures
    import multiprocessing

    return concurrent.futures.ProcessPoolExecutor(max_workers=workers, mp_context=multiprocessing.get_context("spawn"))


def _run_on_cluster(scheduler: Any) -> Runner:
    """Runs the tasks on the Dask cluster of `scheduler` (an address or a Client), yielding
    (index, outcome) as jobs finish. The argument is checked here, the connection made by the run."""
    distributed = _import_distributed()
    if not isinstance(scheduler, distributed.Client) and (not isinstance(scheduler, str) or not scheduler.strip()):
        raise JobError(
            f"scheduler = {scheduler!r}: must be the address of a Dask scheduler (e.g. "
            "'tcp://host:8786') or a distributed.Client"
        )

    def run(tasks: List[Task]) -> Iterator[Tuple[int, Dict[str, Any]]]:
        client = scheduler if isinstance(scheduler, distributed.Client) else _connect(distributed, scheduler)
        try:
            futures = {client.submit(plan_job_file, *task, pure=False): i for i, task in enumerate(tasks)}
            for future in distributed.as_completed(list(futures)):
                yield futures[future], _outcome(future)
        finally:
            if client is not scheduler:
                client.close()

    return run


def _import_distributed() -> Any:
    try:
        import distributed
    except ImportError as error:
        raise JobError(
            "--scheduler needs Dask's distributed scheduler, which is not installed: "
            "pip install 'dispkin[distributed]' (or pip install 'dask[distributed]')"
        ) from error
    return distributed


#: How long connecting to a Dask scheduler may take (s) before `dispkin batch` gives up.
CONNECT_TIMEOUT = 10.0


def _connect(distributed: Any, address: str) -> Any:
    """A Client of the scheduler at `address`; a JobError naming it when there is none."""
    try:
        return distributed.Client(address, timeout=CONNECT_TIMEOUT)
    except (OSError, TimeoutError, ValueError, TypeError) as error:
        raise JobError(f"--scheduler = {address!r}: cannot connect to a Dask scheduler there: {error}") from error


def _outcome(future: Any) -> Dict[str, Any]:
    """The outcome of a finished job; a worker that could not plan it (a cluster's worker that
    died, a worker without dispkin) fails the job alone."""
    try:
        return future.result()
    except Exception as error:  # noqa: BLE001 - the job's failure, not the batch's
        return {"error": f"the worker planning it failed: {type(error).__name__}: {error}"}


def _result(job: str, folder: pathlib.Path, task: Task, outcome: Dict[str, Any]) -> BatchResult:
    if "error" in outcome:
        # The worker read the job at its absolute path: name it as given, as `dispkin plan` does.
        error = outcome["error"]
        return BatchResult(
            job, folder, FAILED, error=job + error[len(task[0]) :] if error.startswith(task[0]) else error
        )
    return BatchResult(
        job,
        folder,
        LIMITS_BROKEN if outcome["violations"] else PLANNED,
        outcome["duration"],
        outcome["binding"],
        list(outcome["violations"]),
        written=[pathlib.Path(p) for p in outcome["written"]],
    )


def _report(progress: Progress, result: BatchResult, done: int, total: int) -> None:
    if result.status == FAILED:
        what = "FAILED: " + result.error
    else:
        broken = f", breaks {len(result.violations)} machine limit(s)" if result.violations else ""
        what = f"{result.duration:.4f} s{broken}"
    progress.stage(f"{done}/{total} jobs: {result.job}: {what}")


def _write_summary(directory: pathlib.Path, results: List[BatchResult]) -> pathlib.Path:
    path = directory / SUMMARY_FILE
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=SUMMARY_COLUMNS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(result.row() for result in results)
    try:
        path.write_text(text.getvalue(), encoding="utf-8")
    except OSError as error:
        raise JobError(
            f"-o DIR = {str(directory)!r}: {SUMMARY_FILE} cannot be written: {error.strerror or error}"
        ) from error
    return path


def run_batch(
    jobs: Sequence[str],
    outdir: str,
    workers: Optional[int],
    scheduler: Optional[str],
    plot: bool,
    out: TextIO,
    allow_violations: bool = False,
    progress: Optional[Progress] = None,
    errors: Optional[TextIO] = None,
) -> int:
    """`dispkin batch`: plan the jobs (:func:`batch`), print a line per job that failed or
    breaks a machine limit and the totals. Returns 0; 1 when a job failed;
    EXIT_LIMITS_BROKEN when a trajectory breaks a machine limit unless `allow_violations`."""
    from .commands import EXIT_LIMITS_BROKEN

    errors = errors or sys.stderr
    results = batch(jobs, outdir, workers, scheduler, plot, progress)
    if progress is not None and progress.enabled:
        progress.finish(f"{len(results)} job(s) done")
    failed = [r for r in results if r.status == FAILED]
    broken = [r for r in results if r.status == LIMITS_BROKEN]
    for r in failed:  # a job's error names its file, except when the worker planning it stopped
        print(f"dispkin batch: {r.error if r.error.startswith(r.job) else r.job + ': ' + r.error}", file=errors)
    for r in broken:
        print(f"dispkin batch: {r.job}: the trajectory breaks {len(r.violations)} machine limit(s):", file=errors)
        for line in r.violations:
            print("  " + line, file=errors)
    print(
        f"{len(results) - len(failed)} of {len(results)} job(s) planned into {outdir}"
        + (f", {len(broken)} breaking a machine limit" if broken else "")
        + f"; summary: {pathlib.Path(outdir) / SUMMARY_FILE}",
        file=out,
    )
    if failed:
        print(f"dispkin batch: {len(failed)} of {len(results)} job(s) failed", file=errors)
        return 1
    if broken and not allow_violations:
        print(
            f"dispkin batch: {len(broken)} job(s) break a machine limit (use --allow-violations to accept it)",
            file=errors,
        )
        return EXIT_LIMITS_BROKEN
    return 0
