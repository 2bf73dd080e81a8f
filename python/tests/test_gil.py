"""restore() releases the GIL while it works: another Python thread runs meanwhile, and two
restorations in two threads give what each gives alone."""

import threading
import time

import numpy as np

import resharp


def test_another_thread_runs_while_restore_works(example):
    V, F = example
    calls = []  # (start, end) of each restore() in the worker

    def work():
        for _ in range(4):
            start = time.perf_counter()
            resharp.restore(V, F, threads=1)
            calls.append((start, time.perf_counter()))

    worker = threading.Thread(target=work)
    ticks = []  # when this thread ran; it sleeps between ticks, so only with the GIL free
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.0002)
    worker.join()
    ticks = np.array(ticks)
    # Held for the whole call, the GIL would leave no tick in the middle half of any call.
    inside = sum(np.count_nonzero((ticks > a + (b - a) / 4) & (ticks < b - (b - a) / 4))
                 for a, b in calls)
    assert len(calls) == 4 and sum(b - a for a, b in calls) > 0.02
    assert inside >= 8, f"{inside} ticks inside {len(calls)} calls"


def test_two_threads_restore_at_once(example):
    V, F = example
    alone = resharp.restore(V, F)
    shifted = V + 100.0
    results = {}

    def work(name, vertices):
        results[name] = resharp.restore(vertices, F, threads=1)

    threads = [threading.Thread(target=work, args=(name, vertices))
               for name, vertices in (("a", V), ("b", shifted), ("c", V))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for name in "ac":
        assert np.array_equal(results[name].vertices, alone.vertices)
        assert np.array_equal(results[name].faces, alone.faces)
    assert np.array_equal(results["b"].vertices[:len(V)], shifted)
