"""Keep freed memory in the process heap, so that each frame's large arrays reuse pages instead of faulting in new ones.

A 640x480 frame's inference allocates and frees tens of megabytes (the network's activations, its 12 MB category
probabilities, a 300 KB mask per instance at camera resolution). glibc's allocator serves blocks above its mmap
threshold with fresh mappings and returns the heap's free top to the kernel above its trim threshold; both
thresholds move with the history of allocations, so whether a process faults in its pages anew every frame
depended on what it had allocated before. Measured on the saved held-out LIBERO frames (separate processes, same
code): some processes took ~7,000-10,000 minor page faults per frame and ~30-50 ms more per frame than others that
took none. Fixing both thresholds makes every process take the fast path.

The cost: up to TRIM_THRESHOLD_B of freed memory stays with the process (peak RSS over 40 saved LIBERO frames,
five processes each: 768-778 MB with, 767-772 MB without; a LIBERO bench process ~5 GB either way). Process-wide,
applied once, by the `learned` segmenter's constructor; glibc only (elsewhere a no-op)."""

from __future__ import annotations

import ctypes
import threading

# glibc's mallopt parameters (malloc.h)
M_TRIM_THRESHOLD = -1
M_MMAP_THRESHOLD = -3
MMAP_THRESHOLD_B = 32 * 1024 * 1024  # glibc's maximum (HEAP_MAX / 2 on 64-bit): blocks up to this come from the heap
TRIM_THRESHOLD_B = 256 * 1024 * 1024  # free memory at the heap's top returned to the kernel only above this

_LOCK = threading.Lock()
_applied: bool | None = None


def keep_freed_memory() -> bool:
    """Fix glibc's mmap and trim thresholds (once per process); True when applied, False where the C library has
    no `mallopt` (not glibc) or refused a value."""
    global _applied
    with _LOCK:
        if _applied is None:
            mallopt = _mallopt()
            _applied = bool(
                mallopt and mallopt(M_MMAP_THRESHOLD, MMAP_THRESHOLD_B) and mallopt(M_TRIM_THRESHOLD, TRIM_THRESHOLD_B)
            )  # mallopt returns 1 on success
        return _applied


def _mallopt():
    """The C library's `mallopt`, looked up among the symbols already in the process (no library search, no
    subprocess); None where there is none."""
    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError):
        return None
    mallopt.argtypes = (ctypes.c_int, ctypes.c_int)
    mallopt.restype = ctypes.c_int
    return mallopt
