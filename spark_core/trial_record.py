"""A TrialConfig as plain JSON and back, losslessly: what the console records when it queues a trial, so a trial
queued before a restart runs as it was asked for (the noise model and capture settings included)."""

from __future__ import annotations

import dataclasses
from typing import Any

from .trial import TrialConfig, TrialConfigError

_TUPLES = ("cameras", "breakpoints")


def config_record(config: TrialConfig) -> dict[str, Any]:
    """The config as JSON types. `noise` keeps the NoiseModel's fields (and a description for readers)."""
    out = dataclasses.asdict(config)
    out["noise"] = {**dataclasses.asdict(config.noise), "description": config.noise.describe()}
    out["capture"] = None if config.capture is None else dataclasses.asdict(config.capture)
    return out


def config_from_record(record: dict[str, Any]) -> TrialConfig:
    """The config `config_record` wrote, checked. TrialConfigError if it cannot be rebuilt as asked (an older
    record, or a task or backend this installation no longer has)."""
    try:
        return _rebuild(record)
    except TrialConfigError:
        raise
    except (TypeError, ValueError) as e:  # a field of the wrong shape, or settings a dataclass refuses
        raise TrialConfigError(f"recorded config: {e}") from None


def _rebuild(record: dict[str, Any]) -> TrialConfig:
    from .perception.noisy_segmenter import NoiseModel

    fields = {f.name for f in dataclasses.fields(TrialConfig)}
    unknown = sorted(set(record) - fields)
    if unknown:
        raise TrialConfigError(f"recorded config has fields this version does not know: {', '.join(unknown)}")
    values = dict(record)
    for name in _TUPLES:
        if values.get(name) is not None:
            values[name] = tuple(values[name])
    noise = values.pop("noise", None)
    if isinstance(noise, dict):
        values["noise"] = NoiseModel(**{k: v for k, v in noise.items() if k != "description"})
    elif noise is not None and values.get("segmenter") == "sim-noisy":
        raise TrialConfigError(f"noise: recorded only as a description ({noise!r}), not its settings")
    if isinstance(values.get("capture"), dict):
        from .sim.capture import CaptureConfig

        capture = dict(values["capture"])
        capture["cameras"] = tuple(capture.get("cameras", ()))
        values["capture"] = CaptureConfig(**capture)
    return TrialConfig(**values).check()


__all__ = ["config_from_record", "config_record"]
