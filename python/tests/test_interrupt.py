"""Ctrl-C stops restore() between two stages: KeyboardInterrupt comes out of the call itself."""

import _thread
import threading
import traceback

import numpy as np
import pytest

import resharp


def test_ctrl_c_stops_restore_inside_the_call(example):
    V, F = example
    # 40 copies side by side (1.6M triangles): restoring them takes far longer than the 0.1 s
    # after which the interrupt comes, so it arrives while restore() works.
    copies = 40
    width = np.ptp(V[:, 0]) * 1.5
    vertices = np.concatenate([V + [i * width, 0.0, 0.0] for i in range(copies)])
    faces = np.concatenate([F + i * len(V) for i in range(copies)])
    timer = threading.Timer(0.1, _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt) as raised:
            resharp.restore(vertices, faces)
    finally:
        timer.cancel()
    # Raised by the compiled restore(), not by the interpreter after the call returned.
    innermost = traceback.extract_tb(raised.value.__traceback__)[-1]
    assert innermost.name == "restore" and "_resharp.restore" in innermost.line

