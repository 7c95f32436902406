"""tessera.world: unbounded worlds of deterministic tiles (the library's tessera/world.hpp).

A world is an unbounded grid of square (2D) or cubic (3D) tiles of one size; tile (x, y[, z])
covers [x S, (x + 1) S) x [y S, (y + 1) S) [x [z S, (z + 1) S)]. Tiles are made in phases
((x mod 2) + 2 (y mod 2) in 2D, the parities in Gray-code order in 3D), each grown next to its finished neighbours of
earlier phases, so a tile depends only on the exemplar, the options, the seed, its
coordinates and those neighbours: the same tile whatever made it, in which order or where.

    maker = tessera.world.TileMaker(ex, tile_size=12, seed=3)
    world = tessera.world.World(ex, tile_size=12, seed=3)      # tiles on demand
    part = world.around((40, 25), 10)                          # an Arrangement
    built = tessera.world.build(ex, ((0, 4), (0, 4)), 12, seed=3)   # 16 tiles on Dask
    built.merged()

Tile coordinates are tuples (x, y) or (x, y, z). Tiles travel in a compact form: a dict of
numpy arrays holding exactly what the tile's file holds (to_compact describes its keys), so
they pickle and cross processes unchanged. Ranges of tiles (`tiles` of build and build_local)
are boxes with exclusive ends, as in range() and in ``tessera world --tiles X0:X1,Y0:Y1``:
((0, 4), (0, 3)) or "0:4,0:3" holds the tiles 0 <= x < 4, 0 <= y < 3.
"""

import collections
import os
import time

from . import _options, _tessera
from ._tessera import Exemplar
from ._world_ranges import tiles_of
from .errors import Cancelled, OptionError, TesseraError

__all__ = ["ClusterUnavailable", "TileMaker", "World", "WorldTiles", "build", "build_local", "closure",
           "from_compact", "merge", "tile_hash", "tile_json", "to_compact"]


# How tiles are made: grown by neighbourhood matching (tessera.Grower's keywords) or
# synthesized by the PCF method next to their neighbours' fixed elements (the keywords of
# tessera.synthesize(method="pcf"); 2D, single-sample elements).
_METHODS = ("grow", "pcf")


class ClusterUnavailable(TesseraError, ConnectionError):
    """No Dask scheduler answers at the address given, or it has no worker, within the
    timeout; the message names the address."""


# ---- tiles as data ------------------------------------------------------------------------

def to_compact(tile):
    """The compact form of a tile (an Arrangement whose domain is a box), a dict:
    dimension; box_min, box_max (d,) the tile's box; types (dicts as Exemplar.types, with
    reference as an R x d array); attribute_names; per element sample_counts (int32),
    classes (int32), radii, orientations (E x 4, w, x, y, z), scales, ids (uint64), locked
    (bool), attributes (E x A); per sample positions (S x d) and times. Element centres are
    computed from the samples when read back, as a reader of the tile's file computes them."""
    return _tessera.tile_to_compact(tile)


def from_compact(tile):
    """The Arrangement of a compact tile. OptionError naming the key at fault, InputError for
    data that break the model's invariants."""
    return _tessera.tile_from_compact(tile)


def tile_json(tile):
    """A tile (compact or an Arrangement) in the native JSON format, as its file holds it."""
    return _tessera.tile_json(tile)


def tile_hash(tile):
    """The content hash of a tile (compact or an Arrangement): 16 hex digits of FNV-1a 64 of
    tile_json, as a world directory's index.json records it."""
    return _tessera.tile_hash(tile)


def merge(tiles):
    """Tiles merged into one Arrangement (ids renumbered in order, the union of their boxes as
    domain). tiles: a WorldTiles, a dict {coord: compact tile} (merged in coordinate order)
    or a sequence of compact tiles (in the order given). OptionError when there is none."""
    if isinstance(tiles, WorldTiles):
        tiles = tiles.tiles
    if isinstance(tiles, dict):
        tiles = [tiles[coord] for coord in sorted(tiles)]
    return _tessera.merge_tiles(list(tiles))


def closure(tiles, dimension):
    """The tiles of `tiles` (coordinates) and every tile they depend on, transitively, sorted
    by phase and then by coordinates: the tiles a build of `tiles` makes."""
    return _tessera.tile_closure(tiles, dimension)


# ---- makers -------------------------------------------------------------------------------

class TileMaker(_tessera.TileMaker):
    """Makes the tiles of one world: TileMaker(exemplar, tile_size, **options).

    exemplar   an Exemplar or a path to one.
    tile_size  the edge of a tile, at least min_tile_size (the neighbourhood the growth needs;
               the OptionError naming tile_size says how much for this exemplar).
    method     "grow" (default): tiles grown by neighbourhood matching, 2D and 3D, with the
               keywords of tessera.Grower; "pcf": tiles synthesized by the PCF method next to
               their neighbours' fixed elements (2D, single-sample elements), with the keywords
               of tessera.synthesize(method="pcf"). An option of the other method is an
               OptionError.
    options    the method's keywords (listed below); threads is the thread count of each
               tile and changes no tile.

    make(coord, neighbours=None) returns the tile (compact form) grown next to `neighbours`,
    the finished tiles of dependencies(coord) as {coord: tile} or (coord, tile) pairs
    (InputError when one is missing or another tile is given). phase(coord), phases,
    dependencies(coord), margin, min_tile_size, dimension, tile_size and fingerprint describe
    the world. make() releases the GIL and may run on several threads at once.
    """

    def __init__(self, exemplar, tile_size, method="grow", **options):
        super().__init__(_as_exemplar(exemplar), tile_size, _method_options("TileMaker", method, options))

    _options.with_signature(__init__, ("self", "exemplar", "tile_size", "method"), _METHODS)


class World(_tessera.World):
    """A world answered on demand: World(exemplar, tile_size, cache_dir=None, **options), with
    the arguments of TileMaker. Only the tiles asked for and their dependencies are made; every
    finished tile is kept in memory and, with `cache_dir`, as tile_X_Y[_Z].json files there,
    read back instead of made again (FileError when it cannot be written, OptionError when it
    holds another world's tiles). Any order of requests gives the tiles a build gives.

    tile(coord) the finished tile (compact form); tiles_around(point, radius) the tiles whose
    box comes within radius of point; around(point, radius) those tiles merged into an
    Arrangement; made (tiles this object made), known (tiles in memory). A World serves one
    thread at a time (RuntimeError when another thread is using it); it releases the GIL while
    it makes tiles.
    """

    def __init__(self, exemplar, tile_size, cache_dir=None, method="grow", **options):
        options = _method_options("World", method, options)
        cache_dir = None if cache_dir is None else os.fspath(cache_dir)
        super().__init__(_as_exemplar(exemplar), tile_size, cache_dir, options)

    _options.with_signature(__init__, ("self", "exemplar", "tile_size", "cache_dir", "method"), _METHODS)


class WorldTiles:
    """The tiles of a build. tiles: {coord: compact tile} of the tiles asked for, in
    coordinate order; hashes: {coord: tile_hash}; merged(): the tiles as one Arrangement
    (what ``tessera world --merge`` writes); made: the tiles made, neighbours outside the
    range included; dimension, tile_size."""

    def __init__(self, tiles, made, dimension, tile_size):
        self.tiles = {coord: tiles[coord] for coord in sorted(tiles)}
        self.made, self.dimension, self.tile_size = made, dimension, tile_size
        self._hashes = None

    @property
    def hashes(self):
        if self._hashes is None:
            self._hashes = {coord: tile_hash(tile) for coord, tile in self.tiles.items()}
        return self._hashes

    def merged(self):
        return merge(self.tiles)

    def __len__(self):
        return len(self.tiles)

    def __repr__(self):
        return "<tessera.world.WorldTiles %dD, %d tiles of size %g>" % (self.dimension, len(self), self.tile_size)


# ---- builds -------------------------------------------------------------------------------

def build_local(exemplar, tiles, tile_size, *, method="grow", progress=None, **options):
    """The tiles `tiles` of a world, made in this process one after another (a reference for
    build, and enough for small ranges); returns a WorldTiles.

    tiles     a box of tiles with exclusive ends, ((x0, x1), (y0, y1)[, (z0, z1)]) or its text
              "X0:X1,Y0:Y1[,Z0:Z1]", or a list of boxes that do not overlap. The neighbours of
              earlier phases outside the range are made too (a tile needs them) but not returned.
    progress  optional callable, called after each tile with a dict (stage "tile", iteration
              = tiles made, iterations = tiles to make, energy, elapsed, fraction); returning
              False stops the build (Cancelled).
    Other arguments and options as for TileMaker. Raises OptionError naming `tiles`,
    `tile_size` or the option at fault, InputError for an invalid exemplar.
    """
    options = _method_options("build_local", method, options)
    exemplar, _ = _canonical(exemplar)
    wanted = tiles_of(tiles, exemplar.dimension)
    report = _reporter(progress)
    maker = TileMaker(exemplar, tile_size, **options)
    made = {}
    order = closure(wanted, exemplar.dimension)
    for done, coord in enumerate(order, 1):
        made[coord] = maker.make(coord, {d: made[d] for d in maker.dependencies(coord)})
        report(done, len(order))
    return WorldTiles({coord: made[coord] for coord in wanted}, len(made), exemplar.dimension, maker.tile_size)


def build(exemplar, tiles, tile_size, client=None, *, method="grow", timeout=30, n_workers=2, retries=2, progress=None,
          tiles_per_task=None, **options):
    """The tiles `tiles` of a world, made on Dask.distributed, a task per group of tiles of one
    phase; returns a WorldTiles whose tiles are byte-identical to build_local's and to World's.

    tiles      a box of tiles with exclusive ends, ((x0, x1), (y0, y1)[, (z0, z1)]) or its text
               "X0:X1,Y0:Y1[,Z0:Z1]", or a list of boxes that do not overlap. The neighbours of
               earlier phases outside the range are made too but not returned.
    tile_size  the edge of a tile (see TileMaker).
    client     None: a LocalCluster of `n_workers` worker processes of one thread each, started
               for this call and closed after it (a script doing this must guard its main code
               with ``if __name__ == "__main__":``, as Dask's worker processes import it); a
               distributed.Client or Cluster to use (left open); or a scheduler address
               "tcp://host:port" (connected to for this call). Workers need this tessera
               installed, and the files the exemplar's domain names.
    timeout    seconds to wait for the scheduler to answer and for a first worker:
               ClusterUnavailable (a ConnectionError) naming the address after that.
    retries    how many times a tile whose task raised is run again. A worker that dies is not
               a failure of its tiles: the scheduler makes them, and the finished tiles it held,
               again on other workers, identical.
    progress   optional callable, called as tiles finish with a dict (stage "tile", iteration,
               iterations, energy, elapsed, fraction); returning False cancels the tiles under
               way and raises Cancelled.
    tiles_per_task
               the most tiles one task makes (tiles of one phase in a block of tiles, made one
               after the other on one worker): None (default) chooses as many as leave four
               tasks per worker thread in each phase, up to 16; 1 makes a task of each tile.
               A task costs a few milliseconds of scheduling whatever it holds. No tile changes.
    options    the growth's keywords as for TileMaker; threads (each tile's growth) defaults to 1
               here, since the workers run tiles side by side.

    The tiles and options are checked before any cluster is reached: OptionError naming
    `tiles`, `tile_size` or the option, InputError for an invalid exemplar. A tile's error on
    a worker is raised here as the library raised it.
    """
    options = _method_options("build", method, options)
    exemplar, text = _canonical(exemplar)
    wanted = tiles_of(tiles, exemplar.dimension)
    report = _reporter(progress)
    if not (isinstance(retries, int) and not isinstance(retries, bool) and retries >= 0):
        raise OptionError("retries must be an integer >= 0, got %r" % (retries,))
    if not (isinstance(timeout, (int, float)) and not isinstance(timeout, bool) and timeout > 0):
        raise OptionError("timeout must be a number of seconds > 0, got %r" % (timeout,))
    if not (tiles_per_task is None or (isinstance(tiles_per_task, int) and not isinstance(tiles_per_task, bool)
                                       and tiles_per_task >= 1)):
        raise OptionError("tiles_per_task must be None or an integer >= 1, got %r" % (tiles_per_task,))
    if options.get("threads") is None:
        options["threads"] = 1
    maker = TileMaker(exemplar, tile_size, **options)  # checks every option here, before the cluster
    from . import _world_dask  # imports distributed, which tessera needs for this call only
    world = _world_dask.recipe(text, maker.tile_size, options, maker.fingerprint)
    order = closure(wanted, exemplar.dimension)
    largest_phase = max(collections.Counter(maker.phase(c) for c in order).values())
    with _world_dask.connected(client, timeout, n_workers, ClusterUnavailable) as dask:
        workers = sum(dask.nthreads().values())
        side = _world_dask.block_side(tiles_per_task, exemplar.dimension, largest_phase, workers)
        submitted, held = _world_dask.submit(dask, world, order, maker.dependencies, maker.phase, side, retries)
        try:
            made = _world_dask.collect(dask, submitted, wanted, report)
        except BaseException:
            dask.cancel([future for future, _ in submitted] + [held])
            raise
    return WorldTiles(made, len(order), exemplar.dimension, maker.tile_size)


_options.with_signature(build_local, ("exemplar", "tiles", "tile_size"), _METHODS, ("method", "progress"))
_options.with_signature(build, ("exemplar", "tiles", "tile_size", "client"), _METHODS,
                        ("method", "timeout", "n_workers", "retries", "progress", "tiles_per_task"))


def _method_options(name, method, options):
    """The options of `method` ("grow" or "pcf") with the method's name under "method", as the
    library's TileMaker takes them: a TypeError for a keyword neither method has, an
    OptionError for an unknown method or an option of the other one set off its default."""
    chosen = _options.of_method(name, method, _METHODS, options)
    chosen["method"] = method
    return chosen


def _reporter(progress):
    """report(done, total) for a build: calls `progress` with the library's event dict, and
    raises Cancelled when it returns False."""
    if progress is not None and not callable(progress):
        raise OptionError("progress must be callable, got %r" % (progress,))
    start = time.monotonic()

    def report(done, total):
        if progress is None:
            return
        event = {"stage": "tile", "iteration": done, "iterations": total, "energy": 0.0,
                 "elapsed": time.monotonic() - start, "fraction": done / total}
        if progress(event) is False:
            raise Cancelled("the progress callback cancelled the build")

    return report


def _as_exemplar(exemplar):
    if isinstance(exemplar, (str, bytes, os.PathLike)):
        return _tessera.load(os.fsdecode(exemplar), None)
    if not isinstance(exemplar, Exemplar):
        raise OptionError("exemplar must be a tessera.Exemplar or a file path, got %s" % type(exemplar).__name__)
    return exemplar


def _canonical(exemplar):
    """The exemplar as its JSON text and as read back from it: what every worker of a build
    reads, so that all of them, and build_local, grow from the very same numbers."""
    text = _tessera.exemplar_to_json(_as_exemplar(exemplar))
    return _tessera.exemplar_from_json(text, "the world's exemplar"), text
