"""The learned segmenter keeps freed memory in the heap: a frame's large arrays reuse pages (heap.py)."""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap

import pytest

# A fresh process (the allocator's thresholds move with what a process allocated before), allocating as a frame
# does: several large arrays alive together, then all freed. Round 0 holds three 10 MB blocks, rounds 1-3 three of
# 9 MB; the minor page faults of each round.
_PROBE = textwrap.dedent(
    """
    import json, resource, sys
    import numpy as np
    if sys.argv[1] == "keep":
        from spark_core.perception.learned.heap import keep_freed_memory
        assert keep_freed_memory()
    def faults():
        return resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    out = []
    for mb in (10, 9, 9, 9):
        f0 = faults()
        held = [np.ones(mb * 1024 * 1024 // 8) for _ in range(3)]  # touched: every page written
        del held
        out.append(faults() - f0)
    print(json.dumps(out))
    """
)


def _faults(mode: str) -> list[int]:
    done = subprocess.run([sys.executable, "-c", _PROBE, mode], capture_output=True, text=True, check=True)
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="glibc's allocator")
def test_kept_heap_reuses_pages_where_the_default_faults_them_in_again() -> None:
    default, kept = _faults("default"), _faults("keep")
    # default thresholds: the blocks freed together exceed the trim threshold, so the heap's top goes back to the
    # kernel and every round faults its pages in again (hundreds of faults even with transparent huge pages)
    assert min(default[1:]) > 200, default
    # kept: after the first round the blocks' pages are the heap's own, already mapped
    assert kept[0] > 200 and max(kept[1:]) < 20, kept


def test_applied_once_and_reports_it() -> None:
    from spark_core.perception.learned import heap

    first = heap.keep_freed_memory()
    assert heap.keep_freed_memory() is first
    assert first is (sys.platform.startswith("linux") and heap._applied is True)


def test_the_segmenter_applies_it_in_the_process_that_constructs_it() -> None:
    probe = (
        "from spark_core.perception.learned import heap\n"
        "from spark_core.perception.learned.segmenter import LearnedSegmenter\n"
        "assert heap._applied is None\n"
        "LearnedSegmenter()\n"
        "print(heap._applied)\n"
    )
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert done.stdout.strip().splitlines()[-1] == str(sys.platform.startswith("linux"))
