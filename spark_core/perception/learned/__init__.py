"""The `learned` segmenter: camera-only perception from a network trained here on our own renders.

categories.py (what it predicts), model.py (the network), dataset.py and train.py (training only: labels come
from the renderer), segmenter.py (LearnedSegmenter, what trials use), weights/ + MODEL_CARD.md (package data).
"""
