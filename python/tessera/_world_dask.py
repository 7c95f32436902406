"""A range of a world built on Dask.distributed (tessera.world.build).

Each tile is one task whose arguments are the futures of the tiles it depends on, submitted
phase by phase: the scheduler starts a tile once its neighbours are done, wherever they were
made, and the workers fetch the neighbours' compact tiles from each other. Tiles of one phase
never depend on each other, so no phase waits for a gather. A tile's task key names the world
(a hash of its fingerprint and options) and the tile, so a result is never mistaken for
another world's, and a tile lost with a dying worker is made again, identical, elsewhere.

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


def _make_tile(world, coord, *neighbours):
    """One tile; `neighbours` are the finished tiles of its dependencies, in their order."""
    maker = _maker(world)
    return maker.make(coord, list(zip(maker.dependencies(coord), neighbours)))


# ---- on the client ----------------------------------------------------------------------

def _tile_key(world, coord):
    return "tessera-tile-%s-%s" % (world["key"], "_".join(str(c) for c in coord))


def submit(client, world, coords, dependencies, retries):
    """Futures of every tile of `coords` (in phase order, each after its dependencies),
    and the future of the recipe they share."""
    held = client.submit(_hold, world, key="tessera-world-" + world["key"], retries=retries)
    futures = {}
    for coord in coords:
        neighbours = [futures[d] for d in dependencies(coord)]
        futures[coord] = client.submit(_make_tile, held, coord, *neighbours, key=_tile_key(world, coord),
                                       retries=retries)
    return futures, held


def collect(client, futures, wanted, report):
    """The tiles `wanted` once every future is done; report(done, total) is called after each
    tile (a tile made again after a worker died is not counted twice) and may raise."""
    finished = set()
    for future in distributed.as_completed(list(futures.values()), loop=client.loop):
        if future.status == "error":
            future.result()  # raises the tile's error, as the library raised it on the worker
        finished.add(future.key)
        report(len(finished), len(futures))
    return dict(zip(wanted, client.gather([futures[c] for c in wanted])))


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
