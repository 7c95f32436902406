"""A range of a world built on Dask.distributed (tessera.world.build).

The tiles of one phase within a block of tiles are one task (a group; one tile per task with
blocks of 2 tiles along each axis), whose arguments are the futures of the groups its tiles
depend on, submitted phase by phase: the scheduler starts a group once its neighbours are
done, wherever they were made, and the workers fetch the neighbours' compact tiles from each
other. Tiles of one phase never depend on each other, so no phase waits for a gather. A
task costs the scheduler and the workers a few milliseconds whatever it holds (a third of a
170-element tile's own time), which groups of several tiles share. A group's task key names
the world (a hash of its fingerprint and options) and the group, so a result is never
mistaken for another world's, and a group lost with a dying worker is made again, identical,
elsewhere.

This module imports distributed; tessera.world imports it only when a build runs.
"""

import collections
import contextlib
import hashlib
import logging
import socket
import threading

import distributed

from . import _tessera
from .errors import OptionError


def recipe(exemplar_text, tile_size, options, fingerprint):
    """What a worker needs to make the world's tiles; its "key" names the world."""
    digest = hashlib.sha256((fingerprint + "\n" + repr(sorted(options.items()))).encode()).hexdigest()
    return {"key": digest[:16], "exemplar": exemplar_text, "tile_size": tile_size, "options": dict(options)}


# ---- on the workers ---------------------------------------------------------------------

# TileMakers by world key, made once per worker process (indexing the exemplar is the costly
# part of a maker) and shared by the worker's threads (TileMaker.make is thread-safe). A
# long-lived worker serving many worlds keeps the few it used last.
_MAKERS = collections.OrderedDict()
_MAKERS_LOCK = threading.Lock()
_MAKERS_KEPT = 4


def _maker(world):
    with _MAKERS_LOCK:
        maker = _MAKERS.get(world["key"])
        if maker is None:
            exemplar = _tessera.exemplar_from_json(world["exemplar"], "the world's exemplar")
            maker = _tessera.TileMaker(exemplar, world["tile_size"], world["options"])
            _MAKERS[world["key"]] = maker
            while len(_MAKERS) > _MAKERS_KEPT:
                _MAKERS.popitem(last=False)
        _MAKERS.move_to_end(world["key"])
        return maker


def _hold(world):
    """The recipe as a task result: recomputed from the task if the workers holding it die
    (scattered data would be lost with them)."""
    return world


def _make_group(world, coords, *neighbour_groups):
    """The tiles `coords` (of one phase) as {coord: tile}; `neighbour_groups` are the finished
    groups ({coord: tile}) that hold their dependencies."""
    maker = _maker(world)
    finished = {}
    for group in neighbour_groups:
        finished.update(group)
    return {coord: maker.make(coord, [(d, finished[d]) for d in maker.dependencies(coord)]) for coord in coords}


# ---- on the client ----------------------------------------------------------------------

# Groups hold at most this many tiles when their size is chosen for the call.
_MAX_AUTO_GROUP = 16
# An automatic group size leaves at least this many tasks per worker in a phase.
_TASKS_PER_WORKER = 4


def block_side(tiles_per_task, dimension, phase_tiles=0, workers=1):
    """Tiles along each axis of a group's block (even: the phases alternate along each axis, so
    a block of side b holds (b/2)^dimension tiles of each phase). `tiles_per_task`: the most
    tiles a task may hold, or None: as many as leave _TASKS_PER_WORKER tasks per worker in the
    largest phase (`phase_tiles` tiles), up to _MAX_AUTO_GROUP."""
    side = 2
    while True:
        group = (side // 2 + 1) ** dimension  # of the next side, side + 2
        if tiles_per_task is not None:
            if group > tiles_per_task:
                return side
        elif group > _MAX_AUTO_GROUP or phase_tiles < _TASKS_PER_WORKER * workers * group:
            return side
        side += 2


def groups(coords, phase, side):
    """`coords` (in phase order) as (key, members) groups: the tiles of one phase within one
    block of `side` tiles along each axis, in the order of their first tile."""
    members = collections.OrderedDict()
    for coord in coords:
        members.setdefault((phase(coord),) + tuple(c // side for c in coord), []).append(coord)
    return list(members.items())


def _group_key(world, key):
    return "tessera-tiles-%s-%s" % (world["key"], "_".join(str(c) for c in key))


def submit(client, world, coords, dependencies, phase, side, retries):
    """Futures of every group of `coords` (in phase order, each after its dependencies) with
    their tiles, as [(future, members)], and the future of the recipe they share."""
    held = client.submit(_hold, world, key="tessera-world-" + world["key"], retries=retries)
    submitted, group_of = [], {}
    for key, members in groups(coords, phase, side):
        needed = sorted({group_of[d] for coord in members for d in dependencies(coord)})
        future = client.submit(_make_group, held, members, *[submitted[g][0] for g in needed],
                               key=_group_key(world, key), retries=retries)
        for coord in members:
            group_of[coord] = len(submitted)
        submitted.append((future, members))
    return submitted, held


def collect(client, submitted, wanted, report):
    """The tiles `wanted` once every group is done; report(done, total) is called with the
    tiles finished after each group (a group made again after a worker died is not counted
    twice) and may raise."""
    tiles_of = {future.key: len(members) for future, members in submitted}
    total = sum(tiles_of.values())
    finished, done = set(), 0
    for future in distributed.as_completed([f for f, _ in submitted], loop=client.loop):
        if future.status == "error":
            future.result()  # raises the tile's error, as the library raised it on the worker
        if future.key not in finished:
            finished.add(future.key)
            done += tiles_of[future.key]
        report(done, total)
    holding = {}
    for future, members in submitted:
        for coord in members:
            holding[coord] = future
    needed = list(collections.OrderedDict.fromkeys(holding[c] for c in wanted))
    made = {}
    for group in client.gather(needed):
        made.update(group)
    return {coord: made[coord] for coord in wanted}


@contextlib.contextmanager
def connected(client, timeout, n_workers, unavailable):
    """A distributed.Client for `client` (None, a Client, a Cluster or an address), with a
    worker; what this call started is closed on leaving. `unavailable` is the exception class
    raised when no scheduler answers or it has no worker within `timeout` seconds."""
    if isinstance(client, distributed.Client):
        _wait_for_workers(client, str(client.scheduler.address), timeout, unavailable)
        yield client
        return
    with contextlib.ExitStack() as stack:
        if client is None:
            client = stack.enter_context(_local_cluster(n_workers))
        if isinstance(client, distributed.deploy.Cluster):
            address = client.scheduler_address
            client = stack.enter_context(distributed.Client(client, set_as_default=False))
        elif isinstance(client, str):
            address = client
            client = stack.enter_context(_connect(client, timeout, unavailable))
        else:
            raise OptionError("client must be None, a distributed.Client, a Cluster or a scheduler address "
                              "'tcp://host:port', got %r" % (client,))
        _wait_for_workers(client, address, timeout, unavailable)
        yield client


def _local_cluster(n_workers):
    if not (isinstance(n_workers, int) and not isinstance(n_workers, bool) and n_workers >= 1):
        raise OptionError("n_workers must be an integer >= 1, got %r" % (n_workers,))
    # Worker processes of one thread each: tiles run side by side, each on one core.
    return distributed.LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=True,
                                    dashboard_address=None, silence_logs=logging.ERROR)


def _connect(address, timeout, unavailable):
    # The port is tried first with a plain socket: a Client that fails to connect stays half
    # made, and its closing when the interpreter exits waits a minute for a scheduler that
    # never comes. The errors are raised after the except blocks, so as not to keep Dask's
    # traceback (which holds the half-made Client) alive.
    try:
        _reach(address, timeout)
        return distributed.Client(address, timeout=timeout, set_as_default=False)
    except ValueError as e:  # not an address at all
        error = OptionError("client: %r is not a scheduler address such as 'tcp://host:8786' (%s)" % (address, e))
    except (OSError, TimeoutError) as e:
        error = unavailable("client: no Dask scheduler answers at %s (waited %g s): %s" % (address, timeout, e))
    raise error


def _reach(address, timeout):
    """Opens and closes a TCP connection to the scheduler's port (OSError when none answers,
    ValueError when `address` is not a tcp address)."""
    scheme, location = distributed.comm.parse_address(address)
    if scheme not in ("tcp", "tls"):
        raise ValueError("only tcp:// and tls:// addresses are supported")
    host, port = distributed.comm.parse_host_port(location)
    socket.create_connection((host, port), timeout=timeout).close()


def _wait_for_workers(client, address, timeout, unavailable):
    try:
        client.wait_for_workers(1, timeout=timeout)
    except (OSError, TimeoutError) as e:
        raise unavailable("client: the Dask scheduler at %s has no worker (waited %g s): %s"
                          % (address, timeout, e)) from None
