"""Run manifests: what a `spark bench` run records (code, packages, task files, seeds, settings, per-trial
results), re-running a run from its manifest gives the same verdicts, and the dev / held-out splits."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import pytest

from spark_cli import main
from spark_core.bench import manifest as mf
from spark_core.bench.splits import SPLITS, describe, split_of, split_seeds
from spark_core.trace import TraceStore
from spark_core.trial import TrialConfig

ROOT = Path(__file__).resolve().parents[2]


def sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.mark.parametrize(
    "suite,tasks,module",
    [
        ("builtin", ["lift_block", "push_to_zone"], "builtin.py"),
        pytest.param("capbench", ["Lift", "Stack"], "capbench.py", marks=pytest.mark.slow),
    ],
)
def test_a_run_from_its_manifest_gets_the_same_verdicts(suite, tasks, module, tmp_path, capsys):
    import mujoco

    out, rows_1, rows_2 = tmp_path / "run.manifest.json", tmp_path / "rows1.json", tmp_path / "rows2.json"
    url = f"sqlite:///{tmp_path / 'bench.db'}"
    run = ["--tasks", *tasks, "--trials", "2", "--segmenter", "privileged-keypoints"]
    assert main(["bench", suite, *run, "--manifest-out", str(out), "--json", str(rows_1), "--store", url]) == 0
    first = capsys.readouterr().out
    m = json.loads(out.read_text())
    assert m["run"]["suite"] == suite and m["run"]["tasks"] == tasks and m["run"]["seeds"] == [0, 1]
    assert m["environment"]["packages"]["mujoco"] == mujoco.__version__
    assert len(m["environment"]["git"]["commit"]) == 40 and isinstance(m["environment"]["git"]["dirty"], bool)
    assert m["run"]["segmenter"] == {
        "name": "privileged-keypoints",
        "privileged": True,
        "description": m["run"]["segmenter"]["description"],
    }
    assert m["run"]["planner"]["name"] == "reference" and m["run"]["memory"] == {"plan_library": "off"}
    plan = f"spark_core/sim/tasks/reference/{tasks[0]}.yaml"
    assert m["files"][plan] == sha(ROOT / plan) and m["files"][f"spark_core/sim/tasks/{module}"]
    assert [(t["task"], t["seed"]) for t in m["trials"]] == [(t, s) for t in tasks for s in (0, 1)]
    assert all(t["wall_time_s"] > 0 and "tokens" in t and t["cost_usd"] == 0.0 for t in m["trials"])
    assert f"manifest {m['id']}" in first  # printed with the report
    rows = json.loads(rows_1.read_text())
    assert {r["manifest_id"] for r in rows} == {m["id"]}
    batch = TraceStore(url).get_batch(m["batch_id"])  # stored with the batch, complete
    assert batch["spec"]["manifest"]["id"] == m["id"] and len(batch["spec"]["manifest"]["trials"]) == 4

    assert main(["bench", "--from-manifest", str(out), "--json", str(rows_2)]) == 0
    again = capsys.readouterr().out
    assert "all 4 verdicts as recorded" in again
    assert [(r["task"], r["seed"], r["verdict"]) for r in json.loads(rows_2.read_text())] == [
        (t["task"], t["seed"], t["verdict"]) for t in m["trials"]
    ]
    assert f"as {m['id']}" in again  # same run definition, same code and files: same id


def test_a_rerun_names_changed_verdicts_and_environment():
    recorded = {
        "environment": {"git": {"commit": "a" * 40, "dirty": False}, "packages": {"mujoco": "3.3.7"}},
        "files": {"liberopro/x.bddl": "1"},
        "trials": [{"task": "lift_block", "seed": 0, "verdict": "success"}],
    }
    current = {
        "environment": {"git": {"commit": "b" * 40, "dirty": True}, "packages": {"mujoco": "3.5.0"}},
        "files": {"liberopro/x.bddl": "2"},
    }
    assert mf.drift(recorded, current) == [
        f"git commit {'a' * 40} -> {'b' * 40}",
        "the working tree has uncommitted changes",
        "mujoco 3.3.7 -> 3.5.0",
        "file liberopro/x.bddl changed",
    ]
    assert mf.drift(recorded, recorded) == []
    rows = [{"task": "lift_block", "seed": 0, "verdict": "timeout"}]
    assert mf.compare_verdicts(recorded, rows) == ["lift_block seed 0: success -> timeout"]


def test_liberopro_manifest_hashes_the_task_and_init_state_files():
    from spark_core.sim.libero_envs import data_dir, tasks

    task = tasks()[0]
    files = mf.task_files([task.name])
    sums = {
        line.split()[1][2:]: line.split()[0] for line in (data_dir() / "SHA256SUMS").read_text().splitlines() if line
    }
    assert len(files) == 2
    for key, digest in files.items():
        assert digest == sums[key.removeprefix("liberopro/")]  # the data set's own checksums
    template = TrialConfig("", planner="rules", segmenter="sim")
    m = mf.build(suite="liberopro", tasks=[task.name], seeds=split_seeds("heldout"), template=template, split="heldout")
    assert m["run"]["seeds"] == list(range(10, 50)) and m["run"]["seed_meaning"] == "LIBERO-PRO init-state index"
    assert m["run"]["cameras"]["resolution"] == "640x480"


def test_the_manifest_id_follows_what_defines_the_run():
    template = TrialConfig("", segmenter="privileged-keypoints")
    a = mf.build(suite="builtin", tasks=["lift_block"], seeds=range(2), template=template)
    b = mf.build(suite="builtin", tasks=["lift_block"], seeds=range(2), template=template, command="other words")
    c = mf.build(suite="builtin", tasks=["lift_block"], seeds=range(3), template=template)
    assert a["id"] == b["id"] != c["id"] and len(a["id"]) == 12


def test_splits_are_the_documented_ranges():
    assert SPLITS["dev"] == range(0, 10) and SPLITS["heldout"] == range(10, 50) and SPLITS["all"] == range(50)
    assert split_of(range(10, 50)) == "heldout" and split_of(range(0, 5)) is None
    assert describe("heldout", range(10, 50)) == "split heldout (seeds / init states 10-49)"
    assert describe("heldout", range(10, 13)) == "split heldout (seeds / init states 10-49), of it seeds 10-12"
    assert describe(None, range(0, 2)) == "seeds 0-1 (no named split)"
    with pytest.raises(ValueError, match="unknown split 'test'; available: dev, heldout, all"):
        split_seeds("test")


@pytest.mark.parametrize(
    "flags,seed,trials",
    [(["--split", "dev"], 0, 10), (["--split", "heldout"], 10, 40), (["--split", "heldout", "--trials", "3"], 10, 3)],
)
def test_split_flag_sets_the_seeds(flags, seed, trials):
    import argparse

    from spark_cli.bench import register
    from spark_cli.bench_manifest import prepare

    parser = argparse.ArgumentParser()
    register(parser.add_subparsers())
    args = parser.parse_args(["bench", "liberopro", *flags])
    assert prepare(args) is None and (args.seed, args.trials) == (seed, trials)


def test_a_seed_beside_a_split_is_refused_not_dropped(capsys):
    """`--split heldout --seed 15` used to run seeds 10-14 without a word: the split set the first seed itself."""
    import argparse

    from spark_cli.bench import register
    from spark_cli.bench_manifest import prepare

    parser = argparse.ArgumentParser()
    register(parser.add_subparsers())
    args = parser.parse_args(["bench", "liberopro", "--split", "heldout", "--seed", "15", "--trials", "5"])
    assert prepare(args) == 2
    err = capsys.readouterr().err
    assert "--seed 15 and --split heldout both choose the seeds" in err and "10-49" in err


def test_bad_manifests_are_refused_naming_the_file(tmp_path, capsys):
    bad = tmp_path / "bad.json"
    bad.write_text("{not json")
    assert main(["bench", "--from-manifest", str(bad)]) == 2
    assert "manifest" in capsys.readouterr().err and "not JSON" in str(
        pytest.raises(mf.ManifestError, mf.load, bad).value
    )
    bad.write_text(json.dumps({"manifest_version": 99}))
    with pytest.raises(mf.ManifestError, match="manifest_version 99, this version reads 1"):
        mf.load(bad)
    assert main(["bench"]) == 2 and "give a suite, or --from-manifest" in capsys.readouterr().err


def test_throughput_report_names_its_manifest():
    from spark_core.bench import throughput

    run = {"trials": 2, "successes": 2, "wall_s": 10.0, "per_hour": 720.0}
    result = {
        "trials_per_task": 2,
        "workers": 2,
        "segmenter": "privileged-keypoints",
        "suites": {
            "builtin": {
                "tasks": 1,
                "planner": "reference",
                "runs": {"local": run, "ray": run},
                "manifest": {"id": "0123456789ab"},
            }
        },
    }
    assert "run manifests: builtin `0123456789ab`" in throughput.section(result, "spark bench throughput")


def test_every_task_has_its_defining_files_hashed():
    from spark_core.sim.libero_envs import data_dir
    from spark_core.sim.tasks import SUITES

    for suite, tasks in SUITES.items():
        names = list(tasks)[:3] if suite == "liberopro" else list(tasks)
        files = mf.task_files(names)
        for key, digest in files.items():
            path = data_dir() / key.removeprefix("liberopro/") if key.startswith("liberopro/") else ROOT / key
            assert digest == sha(path), key
        plans = [n for n in names if (ROOT / f"spark_core/sim/tasks/reference/{n}.yaml").is_file()]
        assert all(f"spark_core/sim/tasks/reference/{n}.yaml" in files for n in plans)
        assert len(files) >= (2 * len(names) if suite == "liberopro" else 1)
    with pytest.raises(mf.ManifestError, match="task 'juggle': no such task"):
        mf.task_files(["juggle"])


def test_the_memory_regime_hashes_the_plan_library_an_llm_planner_reads(tmp_path):
    from spark_core.trace.library_table import StorePlanLibrary

    lib = StorePlanLibrary(TraceStore(f"sqlite:///{tmp_path / 'lib.db'}"))
    empty = mf.memory_regime(lib, "gemini")
    lib.add("open the drawer", "task: drawer\ntree: {primitive: wait}\n")
    one = mf.memory_regime(lib, "gemini")
    assert empty["plan_library"] == one["plan_library"] == "on" and (empty["plans"], one["plans"]) == (0, 1)
    assert empty["sha256"] != one["sha256"] == mf.memory_regime(lib, "openai")["sha256"]
    assert mf.memory_regime(lib, "rules")["plan_library"] == "off"  # an offline planner reads no examples
    assert mf.memory_regime(None, "gemini") == {"plan_library": "off"}


def test_a_console_batch_manifest_reruns_as_a_bench_run():
    tasks = ("lift_block", "stack_two")
    configs = [TrialConfig(t, seed=s, segmenter="privileged-keypoints") for t in tasks for s in (3, 4)]
    r = mf.rerun(mf.batch_manifest("builtin", configs, "batch-x"))
    assert (r.tasks, r.seed, r.trials, r.executor) == (["lift_block", "stack_two"], 3, 2, "local")
    assert r.template.segmenter == "privileged-keypoints" and r.template.task == ""
    mixed = [*configs, TrialConfig("lift_block", seed=5, segmenter="sim")]
    with pytest.raises(mf.ManifestError, match="per_trial_config"):
        mf.rerun(mf.batch_manifest("builtin", mixed, "batch-y"))


def test_a_measurement_bench_names_the_code_it_ran_on(tmp_path, capsys):
    out, md = tmp_path / "ik.manifest.json", tmp_path / "BENCHMARKS.md"
    assert main(["bench", "ik", "--targets", "3", "--manifest-out", str(out), "--write", str(md)]) == 0
    m = json.loads(out.read_text())
    assert m["run"]["suite"] == "ik" and len(m["environment"]["git"]["commit"]) == 40
    protocol = [line for line in md.read_text().splitlines() if line.startswith("Protocol: ")]
    assert protocol[-1].endswith(f"; run manifest `{m['id']}`")
    with pytest.raises(mf.ManifestError, match="run.tasks is missing"):  # nothing to re-run: no tasks or seeds
        mf.load(out)


def test_a_gzipped_manifest_loads_as_the_plain_one(tmp_path):
    manifest = mf.build(
        suite="builtin",
        tasks=["lift_block"],
        seeds=[0],
        template=TrialConfig(task="lift_block", planner="reference", segmenter="privileged-keypoints"),
    )
    plain, packed = tmp_path / "run.manifest.json", tmp_path / "run.manifest.json.gz"
    mf.save(manifest, plain)
    mf.save(manifest, packed)
    assert packed.read_bytes()[:2] == b"\x1f\x8b"
    assert mf.load(packed) == mf.load(plain)
    packed.write_bytes(packed.read_bytes()[:30])  # cut short: named, not a traceback
    with pytest.raises(mf.ManifestError, match="cannot read it") as e:
        mf.load(packed)
    assert str(packed) in str(e.value)
