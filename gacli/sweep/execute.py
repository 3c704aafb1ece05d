"""Where the points run: here, on local processes (``--jobs N``), or on a Dask cluster (``--scheduler``).

The first point always runs here, with its errors raised: a mistake in the
options (a parameter without a value, a name the grid does not know) is then
one message, not a table of failed rows. The rest go out in chunks, a few per
worker, so that a slow corner of the grid does not leave the others idle.
Whatever ran them, the rows come back in the plan's order: the same sweep
gives the same table with any number of jobs or on any cluster.

Local processes are started by ``spawn`` (the same on every platform, and no
fork of a process that holds threads); each receives the job once, through
its initializer. On Dask the job is scattered to every worker once; the
workers need gacli installed, as the command's machine does. ``distributed``
is imported only for ``--scheduler`` (``pip install 'gacli[sweep]'``).
"""

from __future__ import annotations

import math
import pickle
from collections.abc import Callable, Sequence

from gacli.sweep.plan import Plan, SweepError
from gacli.sweep.work import Job, Value, run_chunk, run_point

CHUNKS_PER_WORKER = 4
INSTALL = "pip install 'gacli[sweep]'"

Rows = list[tuple[Value, ...]]
Progress = Callable[[int], None]


def run(job: Job, plan: Plan, *, jobs: int = 1, scheduler: str | None = None,
        progress: Progress | None = None, first: tuple[Value, ...] | None = None) -> Rows:
    """The results of every point, in the plan's order; ``progress(n)`` after each n more points.

    ``first``: the first point's row, when the caller has run it already.
    """
    advance = progress or (lambda n: None)
    first = run_point(job, plan.points[0], strict=True) if first is None else first
    advance(1)
    rest = list(enumerate(plan.points))[1:]
    if scheduler:
        done = _on_dask(job, rest, scheduler, advance)
    elif jobs > 1 and len(rest) > 1:
        done = _on_processes(job, rest, jobs, advance)
    else:
        done = []
        for item in rest:
            done += run_chunk(job, [item])
            advance(1)
    rows: Rows = [first] + [()] * len(rest)
    for index, row in done:
        rows[index] = row
    return rows


def chunks(items: Sequence, workers: int) -> list[list]:
    """``items`` cut into about CHUNKS_PER_WORKER pieces per worker, in order."""
    if not items:
        return []
    size = max(1, math.ceil(len(items) / (max(1, workers) * CHUNKS_PER_WORKER)))
    return [list(items[i:i + size]) for i in range(0, len(items), size)]


# -- local processes ------------------------------------------------------------

_INSTALLED: list[Job] = []


def _install(payload: bytes) -> None:
    """A worker's initializer: the job, once per process."""
    _INSTALLED[:] = [pickle.loads(payload)]


def _installed_chunk(chunk):
    return run_chunk(_INSTALLED[0], chunk)


def _on_processes(job: Job, items, jobs: int, advance: Progress):
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor, as_completed

    payload = pickle.dumps(job, protocol=pickle.HIGHEST_PROTOCOL)
    context = multiprocessing.get_context("spawn")
    done = []
    with ProcessPoolExecutor(max_workers=jobs, mp_context=context, initializer=_install,
                             initargs=(payload,)) as pool:
        futures = [pool.submit(_installed_chunk, chunk) for chunk in chunks(items, jobs)]
        for future in as_completed(futures):
            rows = future.result()
            done += rows
            advance(len(rows))
    return done


# -- a Dask cluster ---------------------------------------------------------------

def _on_dask(job: Job, items, address: str, advance: Progress):
    distributed = require_distributed()
    try:
        client = distributed.Client(address, timeout="20s", set_as_default=False)
    except (OSError, TimeoutError, ValueError) as exc:
        raise SweepError(f"--scheduler {address}: cannot reach a Dask scheduler there ({exc})") from None
    done = []
    with client:
        workers = max(1, sum(client.nthreads().values()))
        remote = client.scatter(job, broadcast=True, hash=False)
        futures = [client.submit(run_chunk, remote, chunk, pure=False) for chunk in chunks(items, workers)]
        for future in distributed.as_completed(futures, loop=client.loop):
            rows = future.result()
            done += rows
            advance(len(rows))
    return done


def require_distributed():
    """Dask's ``distributed``, or a SweepError that says what to install."""
    try:
        import distributed
    except ImportError:
        raise SweepError(f"--scheduler needs Dask's distributed, which is not installed: {INSTALL}") from None
    return distributed
