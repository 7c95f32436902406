"""Benchmark B7-dask: worlds of the two-class exemplar built by tessera.world.build on a
2-worker LocalCluster (one thread each), as a markdown table for docs/benchmarks.md.

    PYTHONPATH=build/python python3 bench/world_dask.py EXAMPLES_DIR [--quick]

Times exclude starting the cluster (measured once and reported) and include submitting the
tasks, making every tile of the closure and gathering the range's tiles to the client."""

import os
import sys
import time

import distributed
import logging

import tessera
import tessera.world as world

TILE = 12.0
SIDES = (4, 8, 16, 32)


def main():
    examples = sys.argv[1]
    sides = SIDES[:3] if "--quick" in sys.argv else SIDES
    exemplar = tessera.load(os.path.join(examples, "two_class_2d.json"))
    start = time.monotonic()
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=logging.ERROR) as cluster, distributed.Client(cluster) as client:
        startup = time.monotonic() - start
        world.build(exemplar, ((0, 2), (0, 2)), TILE, client=client, seed=1)  # workers index the exemplar once
        print("| scenario | tiles | made | elements | s | tiles / s | elements / s | s per made tile / 4x4's |")
        print("|---|---|---|---|---|---|---|---|")
        first = None
        for n in sides:
            t0 = time.monotonic()
            built = world.build(exemplar, ((0, n), (0, n)), TILE, client=client, seed=1)
            seconds = time.monotonic() - t0
            elements = sum(len(t["classes"]) for t in built.tiles.values())
            per_tile = seconds / built.made
            first = first or per_tile
            print("| B7-dask %dx%d | %d | %d | %d | %.2f | %.0f | %.0f | %.2f |" % (
                n, n, len(built), built.made, elements, seconds, len(built) / seconds, elements / seconds,
                per_tile / first))
        print()
        print("LocalCluster of 2 worker processes started in %.1f s (not in the times)." % startup)


if __name__ == "__main__":
    main()
