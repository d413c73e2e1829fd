"""Calls from several Python threads at once give the serial results."""

from concurrent.futures import ThreadPoolExecutor

import pounding


def case(omega1):
    r = pounding.run(preset="set1", method="exact", omega1=omega1)
    s = pounding.spectrum(preset="set2", omega1=f"{omega1}:{omega1 + 0.5}:0.1")
    return (
        {k: v for k, v in r.items() if k != "elapsed_ms"},
        [s["left"]["peak_displacement"].tolist(), s["right"]["peak_velocity"].tolist()],
    )


def test_threads_give_the_serial_results():
    values = [0.5 + 0.1 * i for i in range(12)]
    serial = [case(v) for v in values]
    with ThreadPoolExecutor(max_workers=4) as pool:
        parallel = list(pool.map(case, values))
    assert parallel == serial


def test_the_gil_is_released_while_rust_computes():
    """Python goes on in another thread while a spectrum is computed."""
    import threading

    started, done = threading.Event(), threading.Event()
    turns = 0

    def work():
        started.set()
        pounding.spectrum(preset="set1", omega1="0.1:3:0.005")
        done.set()

    thread = threading.Thread(target=work)
    thread.start()
    started.wait()
    while not done.is_set():
        turns += 1
    thread.join()
    # With the GIL held for the whole call, this loop could not turn until
    # the spectrum were done, and would then stop at once.
    assert turns > 1000, turns
