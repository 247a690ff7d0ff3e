"""Train the reader's scorer (`scorer.py`) and reproduce the shipped weights.

    python -m spark_core.planning.learned_reader.train collect var/reader/examples.json
    python -m spark_core.planning.learned_reader.train fit var/reader/examples.json \\
        spark_core/planning/learned_reader/weights/reader.pt

`collect` plans every entry of the dev files (`recipe.DEV_FILES`: the dev half and the probe files already
tuned on; never the test half, never `probe22.yaml`, kept as the reader's unseen check) in its task's scene at seed
0 (sim segmenter) and labels each goal its view affords (`examples.py`); an entry that expects a refusal has no
good goal. `fit` trains the last two MiniLM layers and the head with a listwise loss (softmax over an
instruction's goals and "none of these" at a fixed score; the good goals' total probability, or none's for a
refusal, is maximised), holding out every tenth entry (by a hash of its id) to report accuracy per threshold.
Seeded; ~3 min for the frozen states and ~3 min per epoch on 2 cores."""

from __future__ import annotations

import argparse
import hashlib
import json
import random
import time
from pathlib import Path

import torch
import yaml

from .recipe import DEV_FILES
from .scorer import NONE_SCORE, CrossEncoder

NEGATIVES = 40  # wrong goals kept per instruction (seeded)
EPOCHS = 7
SEED = 0


def held_out(entry_id: str) -> bool:
    return hashlib.sha256(entry_id.encode()).digest()[0] % 10 == 0


def _states(model: CrossEncoder, instruction: str, goals: list[str]) -> tuple[torch.Tensor, torch.Tensor]:
    with torch.no_grad():
        h, mask = model.frozen_states(model.encode_pairs([instruction] * len(goals), goals))
    return h.half(), mask


def fit(examples: list[dict], out: Path, log=print) -> dict:
    torch.manual_seed(SEED)
    rng = random.Random(SEED)
    model = CrossEncoder()
    # keyed by position too: an id may recur across the dev files (each file counts its own ids)
    kept = [
        {**_kept(e, rng), "key": f"{n}|{e['id']}"}
        for n, e in enumerate(examples)
        if e["goals"] and (e.get("refuse") or any(g["good"] for g in e["goals"]))
    ]
    train = [e for e in kept if not held_out(e["id"])]
    val = [e for e in kept if held_out(e["id"])]
    t0 = time.time()
    cache = {e["key"]: _states(model, e["instruction"], [g["text"] for g in e["goals"]]) for e in kept}
    log(f"frozen states of {sum(len(e['goals']) for e in kept)} pairs in {time.time() - t0:.0f} s")
    trained = model.trained_parameters()
    head = set(model.head.parameters())
    opt = torch.optim.AdamW(
        [{"params": [p for p in trained if p not in head], "lr": 1e-4}, {"params": list(head), "lr": 1e-3}],
        weight_decay=0.01,
    )
    model.train()
    for epoch in range(EPOCHS):
        rng.shuffle(train)
        total = 0.0
        for n, e in enumerate(train):
            h, mask = cache[e["key"]]
            scores = torch.cat([model.score_states(h.float(), mask), torch.tensor([NONE_SCORE])])
            good = [i for i, g in enumerate(e["goals"]) if g["good"]] or [len(e["goals"])]  # else: none of these
            loss = -(torch.logsumexp(scores[good], 0) - torch.logsumexp(scores, 0))
            (loss / 8).backward()
            total += float(loss.detach())
            if n % 8 == 7:
                opt.step()
                opt.zero_grad()
        opt.step()
        opt.zero_grad()
        log(f"epoch {epoch}: loss {total / len(train):.3f}; held out: {evaluate(model, val, cache)}")
    out.parent.mkdir(parents=True, exist_ok=True)
    torch.save(model.trained_state(), out)
    return evaluate(model, val, cache)


def _kept(e: dict, rng: random.Random) -> dict:
    """The example with all its good goals and up to `NEGATIVES` wrong ones (seeded): the frozen states are
    computed once for these."""
    good = [g for g in e["goals"] if g["good"]]
    bad = [g for g in e["goals"] if not g["good"]]
    return {**e, "goals": good + rng.sample(bad, min(NEGATIVES, len(bad)))}


@torch.no_grad()
def evaluate(model: CrossEncoder, val: list[dict], cache: dict) -> dict:
    """On held-out instructions, with "none of these" as one more answer: how many goal-stating ones get their
    goal, and how many refusal ones get none, per threshold on the answer's probability (below it: none)."""
    model.eval()
    out: dict = {"held_out": len(val)}
    tops: list[tuple[float, bool, bool]] = []  # (top goal's probability, it is good, the entry wants a refusal)
    for e in val:
        h, mask = cache[e["key"]]
        scores = torch.cat([model.score_states(h.float(), mask), torch.tensor([NONE_SCORE])])
        p = torch.softmax(scores, 0)[:-1]
        k = int(p.argmax())
        tops.append((float(p[k]), bool(e["goals"][k]["good"]), bool(e.get("refuse"))))
    model.train()
    goals = [t for t in tops if not t[2]]
    refusals = [t for t in tops if t[2]]
    for t in (0.3, 0.5, 0.7):
        right = sum(ok and p >= t for p, ok, _ in goals)
        wrong = sum(not ok and p >= t for p, ok, _ in goals)
        refused = sum(p < t for p, _, _ in refusals)
        out[f"p>={t}"] = f"goals {right} right, {wrong} wrong of {len(goals)}; refusals {refused} of {len(refusals)}"
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("collect")
    c.add_argument("out", type=Path)
    f = sub.add_parser("fit")
    f.add_argument("examples", type=Path)
    f.add_argument("out", type=Path)
    args = ap.parse_args()
    torch.set_num_threads(2)
    if args.cmd == "collect":
        from .examples import collect, save

        entries = [e for path in DEV_FILES for e in yaml.safe_load(Path(path).read_text())]
        args.out.parent.mkdir(parents=True, exist_ok=True)
        save(collect(entries, progress=print), args.out)
    else:
        print(json.dumps(fit(json.loads(args.examples.read_text()), args.out)))


if __name__ == "__main__":
    main()
