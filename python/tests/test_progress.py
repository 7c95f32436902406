"""The progress callback: called per iteration, may cancel by returning False or raising,
and the GIL is free while the library works."""
import threading
import time

import pytest

import tessera


def test_progress_is_called_for_every_iteration(two_class):
    events = []
    tessera.synthesize(two_class, iterations=3, progress=events.append)
    iterations = [e for e in events if e["stage"] == "iteration"]
    # A long step re-sends its last event now and then; the steps are the distinct ones.
    steps = [e["iteration"] for k, e in enumerate(iterations) if k == 0 or e["iteration"] != iterations[k - 1]["iteration"]]
    assert steps == [0, 1, 2]
    assert all(e["iterations"] == 3 and e["elapsed"] >= 0 for e in iterations)


def test_returning_false_cancels(two_class):
    calls = []

    def stop_after_first(event):
        calls.append(event)
        return event["stage"] != "iteration"

    with pytest.raises(tessera.Cancelled):
        tessera.synthesize(two_class, iterations=5, progress=stop_after_first)
    assert sum(e["stage"] == "iteration" for e in calls) == 1


def test_an_exception_in_the_callback_cancels_and_propagates(two_class):
    class Stop(Exception):
        pass

    def boom(event):
        if event["stage"] == "iteration":
            raise Stop("enough")

    with pytest.raises(Stop, match="enough"):
        tessera.synthesize(two_class, iterations=5, progress=boom)


def test_pcf_progress_and_cancel(two_class):
    with pytest.raises(tessera.Cancelled):
        tessera.synthesize(two_class, method="pcf", progress=lambda e: False)


def test_the_gil_is_released_during_synthesis(two_class):
    # A Python thread keeps counting while another thread synthesizes a large output.
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    start = time.perf_counter()
    try:
        tessera.synthesize(two_class, scale=16.0, iterations=4, threads=1)  # ~0.4 s
    finally:
        done.set()
        counter.join()
    elapsed = time.perf_counter() - start
    during = [t for t in ticks if start <= t]
    # With the GIL held the counter would be starved for the whole run.
    assert elapsed > 0.05
    assert len(during) >= 10


def test_concurrent_syntheses_from_threads_match_serial_ones(two_class):
    serial = [tessera.synthesize(two_class, seed=s, iterations=2, threads=1).positions for s in (1, 2)]
    results = {}

    def run(seed):
        results[seed] = tessera.synthesize(two_class, seed=seed, iterations=2, threads=1).positions

    threads = [threading.Thread(target=run, args=(s,)) for s in (1, 2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert (results[1] == serial[0]).all() and (results[2] == serial[1]).all()


def test_every_event_of_the_run_reaches_the_callback(two_class):
    # The set-up stage first, the iterations, the end: the events the CLI prints.
    events = []
    tessera.synthesize(two_class, iterations=2, progress=events.append)
    stages = [e["stage"] for e in events]
    assert stages[0] == "init" and stages[-1] == "done"
    assert sorted({e["iteration"] for e in events if e["stage"] == "iteration"}) == [0, 1]
    assert all(set(e) == {"stage", "iteration", "iterations", "energy", "elapsed", "fraction"} for e in events)
    assert [e["elapsed"] for e in events] == sorted(e["elapsed"] for e in events)


@pytest.mark.parametrize("method", ["det", "pcf"])
def test_the_fraction_done_rises_to_one(two_class, method):
    events = []
    tessera.synthesize(two_class, method=method, progress=events.append)
    fractions = [e["fraction"] for e in events]
    assert fractions == sorted(fractions), fractions
    assert 0.0 <= fractions[0] < 0.2 and fractions[-1] == 1.0
    assert any(0.3 < f < 0.9 for f in fractions)
    stages = {e["stage"] for e in events}
    expected = {"det": {"init", "patches", "fill", "iteration", "relax", "repair", "done"},
                "pcf": {"analysis", "init", "iteration", "repair", "done"}}[method]
    assert stages <= expected | {"settle"} and {"init", "iteration", "done"} <= stages
