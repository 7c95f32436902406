"""tessera.world: tiles round-trip through their compact form bit for bit; a range built on Dask
(one worker, two workers, a worker killed mid-build), in one process, by the streaming World in
any order and by `tessera world` gives the same tiles; bad ranges, sizes and schedulers fail
fast with errors that name what is wrong."""
import json
import os
import pickle
import random
import signal
import socket
import subprocess
import time

import numpy as np
import pytest

import tessera
from tessera import world
from conftest import ROOT

TWO_CLASS = ROOT / "examples" / "two_class_2d.json"
RANGE = ((0, 3), (0, 3))  # 9 tiles, 17 made with their neighbours of earlier phases
SIZE = 10.0
SEED = 4


@pytest.fixture(scope="module")
def local():
    """The reference: RANGE made in this process, tile after tile."""
    return world.build_local(TWO_CLASS, RANGE, SIZE, seed=SEED)


def test_local_build_returns_the_range_and_makes_its_neighbours(local):
    assert sorted(local.tiles) == [(x, y) for x in range(3) for y in range(3)]
    assert local.made == len(world.closure(list(local.tiles), 2)) > len(local.tiles)
    assert all(len(h) == 16 for h in local.hashes.values())
    assert len(set(local.hashes.values())) == len(local)
    merged = local.merged()
    assert isinstance(merged, tessera.Arrangement)
    assert len(merged) == sum(len(t["ids"]) for t in local.tiles.values())
    assert merged.domain.bounds == ((0.0, 0.0), (30.0, 30.0))


# ---- the compact form -------------------------------------------------------------------

def rich_arrangement():
    """Every field the format has: multi-sample elements, times, attributes, locks, ids, poses
    and types with a reference layout, a mesh, a colour and dependencies."""
    rng = np.random.default_rng(1)
    positions = rng.uniform(0, 8, (12, 2))
    angles = rng.uniform(0, 3, 6)
    quats = np.column_stack([np.cos(angles / 2), np.zeros(6), np.zeros(6), np.sin(angles / 2)])
    types = [{"name": "pair", "rigid": False, "mesh": "pair.obj", "reference": [(0, 0), (1, 0)], "color": "#112233"},
             {"name": "dot", "floor": True, "depends_on": ["pair"]}]
    return tessera.exemplar(positions, classes=[0, 0, 0, 1, 1, 1], class_names=["pair", "dot"],
                            element_of_sample=np.repeat(np.arange(6), 2), radii=rng.uniform(0, 1, 6),
                            orientations=quats, scales=rng.uniform(0.5, 2, 6), ids=[9, 3, 7, 1, 2, 40],
                            locked=[True, False] * 3, times=rng.uniform(0, 1, 12),
                            attributes=rng.uniform(-1, 1, (6, 2)), attribute_names=["age", "hue"],
                            domain=tessera.Domain.box((0, 0), (8, 8)), types=types)


def test_compact_round_trip_is_exact():
    ex = rich_arrangement()
    compact = world.to_compact(ex)
    assert compact["positions"].dtype == np.float64 and compact["ids"].dtype == np.uint64
    again = pickle.loads(pickle.dumps(compact))  # as Dask ships it
    back = world.from_compact(again)
    assert world.tile_json(back) == world.tile_json(world.from_compact(compact))
    original = json.loads(tessera.world.tile_json(world.from_compact(compact)))
    assert original["attributes"] == ["age", "hue"] and original["types"][1]["depends_on"] == ["pair"]
    np.testing.assert_array_equal(back.times, ex.times)
    np.testing.assert_array_equal(back.ids, ex.ids)
    np.testing.assert_array_equal(back.locked, ex.locked)
    np.testing.assert_array_equal(back.orientations, ex.orientations)


def test_made_tiles_round_trip_exactly_in_2d_and_3d():
    for name, size, coord in (("sticks_2d", 7.0, (1, 0)), ("spheres_3d", 4.0, (0, 0, 0))):
        maker = world.TileMaker(ROOT / "examples" / (name + ".json"), size, seed=1, threads=1)
        neighbours = {d: maker.make(d) for d in maker.dependencies(coord)}
        tile = maker.make(coord, neighbours)
        arrangement = world.from_compact(tile)
        assert world.tile_json(world.to_compact(arrangement)) == world.tile_json(arrangement) == world.tile_json(tile)
        assert world.tile_hash(tile) == world.tile_hash(arrangement)
        assert tile["box_min"].tolist() == [c * size for c in coord]
    assert tile["dimension"] == 3 and tile["positions"].shape[1] == 3
    assert (tile["sample_counts"] == 1).all()


@pytest.mark.parametrize("key, value, message", [
    ("positions", lambda t: t["positions"][:, :1], r"tile\['positions'\] must be an N x 2 array"),
    ("classes", lambda t: t["classes"].astype(float), r"tile\['classes'\] must be an integer array"),
    ("sample_counts", lambda t: t["sample_counts"] * 2, r"tile\['sample_counts'\]"),
    ("ids", lambda t: np.zeros_like(t["ids"]), r"tile\['ids'\]: id 0 repeats"),
    ("locked", lambda t: t["locked"][:3], r"tile\['locked'\] must have \d+ rows"),
    ("colour", lambda t: 1, r"tile: unknown key 'colour'"),
])
def test_a_broken_compact_tile_names_the_key(local, key, value, message):
    tile = dict(local.tiles[(0, 0)])
    tile[key] = value(tile)
    with pytest.raises(tessera.OptionError, match=message):
        world.tile_hash(tile)
    del tile[key]
    if key in local.tiles[(0, 0)]:  # a key the form needs: its absence is named too
        with pytest.raises(tessera.OptionError, match="missing"):
            world.from_compact(tile)
    else:  # an extra key removed: the tile is whole again
        assert world.tile_hash(tile) == world.tile_hash(local.tiles[(0, 0)])


# ---- the maker ----------------------------------------------------------------------------

def test_maker_describes_the_phases_and_checks_its_neighbours(local):
    maker = world.TileMaker(TWO_CLASS, SIZE, seed=SEED)
    assert maker.phases == 4 and maker.dimension == 2 and maker.tile_size == SIZE
    assert [maker.phase(c) for c in ((0, 0), (1, 0), (0, 1), (1, 1), (-1, -1))] == [0, 1, 2, 3, 3]
    assert maker.dependencies((0, 0)) == []
    assert maker.dependencies((1, 0)) == [(0, 0), (2, 0)]
    assert len(maker.dependencies((1, 1))) == 8
    assert maker.min_tile_size <= SIZE and maker.margin > 0
    assert world.tile_hash(maker.make((0, 0))) == local.hashes[(0, 0)]
    with pytest.raises(tessera.InputError, match="neighbour 2,0 .* is not given"):
        maker.make((1, 0), {(0, 0): local.tiles[(0, 0)]})
    with pytest.raises(tessera.OptionError, match=r"coord must be a tile coordinate \(x, y\)"):
        maker.make((1.5, 0))
    with pytest.raises(TypeError, match="unexpected keyword argument 'sed'"):
        world.TileMaker(TWO_CLASS, SIZE, sed=1)
    with pytest.raises(tessera.OptionError, match="energy_factor"):
        world.TileMaker(TWO_CLASS, SIZE, energy_factor=0.5)


# ---- the streaming world ------------------------------------------------------------------

def test_streaming_world_in_random_order_equals_the_build(local):
    streaming = world.World(TWO_CLASS, SIZE, seed=SEED)
    rng = random.Random(7)
    for _ in range(6):
        point, radius = (rng.uniform(4, 26), rng.uniform(4, 26)), rng.uniform(0, 4)
        coords = streaming.tiles_around(point, radius)
        assert coords and all(c in local.tiles for c in coords)
        around = streaming.around(point, radius)
        assert world.tile_json(around) == world.tile_json(world.merge([local.tiles[c] for c in coords]))
    order = list(local.tiles)
    rng.shuffle(order)
    assert {c: world.tile_hash(streaming.tile(c)) for c in order} == local.hashes
    assert streaming.made == streaming.known <= local.made


def test_a_cache_directory_gives_its_tiles_back(tmp_path, local):
    first = world.World(TWO_CLASS, SIZE, tmp_path / "cache", seed=SEED)
    assert world.tile_hash(first.tile((1, 1))) == local.hashes[(1, 1)]
    assert first.made == len(world.closure([(1, 1)], 2)) and (tmp_path / "cache" / "tile_1_1.json").exists()
    second = world.World(TWO_CLASS, SIZE, tmp_path / "cache", seed=SEED)
    assert world.tile_hash(second.tile((1, 1))) == local.hashes[(1, 1)]
    assert second.made == 0
    with pytest.raises(tessera.OptionError, match="another world"):
        world.World(TWO_CLASS, SIZE, tmp_path / "cache", seed=SEED + 1)


def test_a_3d_world_streams_the_tiles_a_build_makes():
    spheres = ROOT / "examples" / "spheres_3d.json"
    built = world.build_local(spheres, "0:1,0:1,1:2", 4.0, seed=2, threads=2)
    streaming = world.World(spheres, 4.0, seed=2, threads=2)
    assert list(built.tiles) == [(0, 0, 1)]
    assert world.tile_hash(streaming.tile((0, 0, 1))) == built.hashes[(0, 0, 1)]
    assert streaming.made == built.made


# ---- on Dask ------------------------------------------------------------------------------

@pytest.mark.parametrize("workers, per_task", [(1, None), (2, None), (2, 4), (1, 9)])
def test_dask_build_equals_the_local_build(local, workers, per_task):
    built = world.build(TWO_CLASS, RANGE, SIZE, n_workers=workers, seed=SEED, tiles_per_task=per_task)
    assert built.hashes == local.hashes
    assert built.made == local.made
    assert world.tile_json(built.merged()) == world.tile_json(local.merged())


def test_tasks_group_the_tiles_of_one_phase_in_blocks():
    from tessera import _world_dask
    # Blocks of b tiles along each axis hold (b / 2)^dimension tiles of each phase.
    assert [_world_dask.block_side(n, 2) for n in (1, 3, 4, 8, 9, 16)] == [2, 2, 4, 4, 6, 8]
    assert [_world_dask.block_side(n, 3) for n in (1, 7, 8, 27)] == [2, 2, 4, 6]
    # Automatic: four tasks per worker thread in the largest phase, at most 16 tiles a task.
    assert _world_dask.block_side(None, 2, phase_tiles=20, workers=2) == 2
    assert _world_dask.block_side(None, 2, phase_tiles=32, workers=2) == 4
    assert _world_dask.block_side(None, 2, phase_tiles=10 ** 6, workers=200) == 8
    assert _world_dask.block_side(None, 3, phase_tiles=10 ** 6, workers=2) == 4
    maker = world.TileMaker(TWO_CLASS, SIZE, seed=SEED)
    order = world.closure([(x, y) for x in range(4) for y in range(4)], 2)
    grouped = _world_dask.groups(order, maker.phase, 4)
    assert sorted(c for _, members in grouped for c in members) == sorted(order)
    for key, members in grouped:
        assert {maker.phase(c) for c in members} == {key[0]} and len(members) <= 4
        assert {tuple(v // 4 for v in c) for c in members} == {key[1:]}
    phases = [key[0] for key, _ in grouped]
    assert phases == sorted(phases)  # each group after the groups it depends on


@pytest.mark.skipif("TESSERA_CLI" not in os.environ, reason="TESSERA_CLI is set by CTest")
def test_the_cli_writes_the_same_tiles(tmp_path, local):
    subprocess.run([os.environ["TESSERA_CLI"], "world", str(TWO_CLASS), "--tiles", "0:3,0:3", "--tile-size", str(SIZE),
                    "--seed", str(SEED), "-o", str(tmp_path / "w"), "-q"], check=True)
    index = json.loads((tmp_path / "w" / "index.json").read_text())
    assert {tuple(t["tile"]): t["hash"] for t in index["tiles"]} == local.hashes


@pytest.mark.parametrize("per_task", [None, 4])
def test_a_worker_killed_mid_build_changes_no_tile(per_task):
    distributed = pytest.importorskip("distributed")
    import logging
    wide = ((0, 4), (0, 4))
    reference = world.build_local(TWO_CLASS, wide, 12.0, seed=5)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=logging.CRITICAL) as cluster, distributed.Client(cluster) as client:
        pids = client.run(os.getpid)
        killed = []

        def kill_the_busiest_worker(event):
            if event["iteration"] >= 4 and not killed:
                busy = {address: keys for address, keys in client.processing().items() if keys}
                victim = max(busy, key=lambda address: len(busy[address]))
                killed.append((victim, len(busy[victim])))
                os.kill(pids[victim], signal.SIGKILL)

        built = world.build(TWO_CLASS, wide, 12.0, client=client, seed=5, progress=kill_the_busiest_worker,
                            tiles_per_task=per_task)
        assert killed and killed[0][1] > 0  # it died with tiles under way
        assert killed[0][0] not in client.scheduler_info()["workers"]
        assert client.status == "running"  # a client given is left open
    assert built.hashes == reference.hashes


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_an_unreachable_scheduler_fails_within_the_timeout():
    address = "tcp://127.0.0.1:%d" % free_port()
    start = time.monotonic()
    with pytest.raises(world.ClusterUnavailable, match="no Dask scheduler answers at " + address) as raised:
        world.build(TWO_CLASS, RANGE, SIZE, client=address, timeout=2)
    assert time.monotonic() - start < 2 + 5
    assert isinstance(raised.value, ConnectionError) and isinstance(raised.value, tessera.TesseraError)
    with pytest.raises(tessera.OptionError, match="client: 'not an address::' is not a scheduler address"):
        world.build(TWO_CLASS, RANGE, SIZE, client="not an address::")


# ---- bad input ----------------------------------------------------------------------------

@pytest.mark.parametrize("tiles, message", [
    (((3, 3), (0, 2)), r"tiles: the range 3:3 along x holds no tile \(ends are exclusive"),
    ("0:2,5:1", r"tiles: the range 5:1 along y holds no tile"),
    ([((0, 3), (0, 3)), "2:4,0:3"], r"tiles: the ranges 0:3,0:3 and 2:4,0:3 overlap"),
    (((0, 3), (0, 3), (0, 1)), r"tiles: a 2D world's tiles are given as \(\(x0, x1\), \(y0, y1\)\)"),
    ("0-3,0-3", r"tiles: a 2D world's tiles are given as"),
    (((0, 2.5), (0, 2)), r"tiles: a 2D world's tiles are given as .* with integer ends"),
    (7, r"tiles must be a box"),
    ([], r"tiles: no range given"),
    (((0, 1 << 12), (0, 1 << 12)), r"tiles: 16777216 tiles, more than"),
])
def test_bad_ranges_fail_before_any_cluster_is_reached(tiles, message):
    start = time.monotonic()
    with pytest.raises(tessera.OptionError, match=message):
        world.build(TWO_CLASS, tiles, SIZE, client="tcp://127.0.0.1:%d" % free_port(), timeout=20)
    with pytest.raises(tessera.OptionError, match=message):
        world.build_local(TWO_CLASS, tiles, SIZE)
    assert time.monotonic() - start < 5


def test_bad_sizes_and_arguments_name_the_parameter():
    unreachable = "tcp://127.0.0.1:%d" % free_port()
    with pytest.raises(tessera.OptionError, match=r"tile_size: 2 is smaller than the neighbourhood .*3\.875"):
        world.build(TWO_CLASS, RANGE, 2.0, client=unreachable, timeout=20)
    with pytest.raises(tessera.OptionError, match="tile_size must be a number"):
        world.build_local(TWO_CLASS, RANGE, "ten")
    with pytest.raises(tessera.OptionError, match="retries must be an integer >= 0"):
        world.build(TWO_CLASS, RANGE, SIZE, client=unreachable, retries=-1)
    with pytest.raises(tessera.OptionError, match="tiles_per_task must be None or an integer >= 1"):
        world.build(TWO_CLASS, RANGE, SIZE, client=unreachable, tiles_per_task=0)
    with pytest.raises(tessera.OptionError, match="timeout must be a number of seconds > 0"):
        world.build(TWO_CLASS, RANGE, SIZE, client=unreachable, timeout=0)
    with pytest.raises(tessera.OptionError, match="client must be None, a distributed.Client"):
        world.build(TWO_CLASS, RANGE, SIZE, client=42)
    with pytest.raises(TypeError, match="build\\(\\) got an unexpected keyword argument 'sed'"):
        world.build(TWO_CLASS, RANGE, SIZE, sed=1)
    with pytest.raises(tessera.OptionError, match="tiles: nothing to merge"):
        world.merge({})


def test_progress_can_stop_a_build():
    events = []
    with pytest.raises(tessera.Cancelled):
        world.build_local(TWO_CLASS, RANGE, SIZE, progress=lambda e: events.append(e) or len(events) < 3)
    assert [e["iteration"] for e in events] == [1, 2, 3]
    assert events[0]["stage"] == "tile" and events[0]["iterations"] == 17
    assert 0 < events[-1]["fraction"] < 1


# ---- tiles by the PCF method --------------------------------------------------------------

POISSON = ROOT / "examples" / "poisson_disk_2d.json"


def test_pcf_tiles_are_the_same_streamed_built_on_dask_and_by_the_cli(tmp_path):
    local = world.build_local(POISSON, ((0, 2), (0, 2)), 10.0, method="pcf", seed=2)
    streaming = world.World(POISSON, 10.0, method="pcf", seed=2, threads=2)
    for coord in [(1, 1), (0, 0), (1, 0), (0, 1)]:
        assert world.tile_hash(streaming.tile(coord)) == local.hashes[coord]
    built = world.build(POISSON, ((0, 2), (0, 2)), 10.0, method="pcf", n_workers=2, seed=2)
    assert built.hashes == local.hashes
    grown = world.build_local(POISSON, ((0, 2), (0, 2)), 10.0, seed=2)
    assert grown.hashes != local.hashes  # the method is not ignored
    exemplar = tessera.load(POISSON)
    expected = exemplar.element_count / exemplar.domain.measure * 4 * 10.0 ** 2
    count = sum(len(t["classes"]) for t in local.tiles.values())
    assert abs(count - expected) < 0.03 * expected  # the exemplar's density, tile by tile
    if "TESSERA_CLI" in os.environ:
        subprocess.run([os.environ["TESSERA_CLI"], "world", str(POISSON), "--method", "pcf", "--tiles", "0:2,0:2",
                        "--tile-size", "10", "--seed", "2", "-o", str(tmp_path / "w"), "-q"], check=True)
        index = json.loads((tmp_path / "w" / "index.json").read_text())
        assert {tuple(t["tile"]): t["hash"] for t in index["tiles"]} == local.hashes


def test_a_pcf_world_names_the_options_of_the_other_method():
    with pytest.raises(tessera.OptionError, match="patch_extent applies to method='grow' only"):
        world.TileMaker(POISSON, 10.0, method="pcf", patch_extent=2.0)
    with pytest.raises(tessera.OptionError, match="method must be 'grow' or 'pcf', got 'det'"):
        world.World(POISSON, 10.0, method="det")
    with pytest.raises(tessera.OptionError, match="method: the PCF method makes 2D worlds"):
        world.TileMaker(ROOT / "examples" / "spheres_3d.json", 10.0, method="pcf")
    assert "method" in str(__import__("inspect").signature(world.build))
