"""Builds dev.yaml and test.yaml from source.txt (run once; the halves are then frozen).

Each line of source.txt is `alias | style | instruction`. The split is fixed by a hash: an entry goes to the
test half when the first byte of sha256("<task>|<instruction>") is odd, else to dev.
Historical: dev.yaml has since grown (later probes, the retired first test half) and test.yaml is now the
second test half (make_test2.py); do not re-run this script over them.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import yaml

HERE = Path(__file__).parent
REFUSALS = ("nonsense", "absent", "ambiguous")
PREFIX = {
    "S": "libero_spatial_swap:pick_up_the_black_bowl_",
    "ST": "libero_spatial_task:pick_up_the_black_bowl_",
    "O": "libero_object_swap:pick_up_the_",
    "OT": "libero_object_task:pick_up_the_",
    "G": "libero_goal_swap:",
    "GT": "libero_goal_task:",
}
SPATIAL = {
    "between": "between_the_plate_and_the_ramekin",
    "center": "from_table_center",
    "drawer": "in_the_top_drawer_of_the_wooden_cabinet",
    "cookienext": "next_to_the_cookie_box",
    "platenext": "next_to_the_plate",
    "ramekinnext": "next_to_the_ramekin",
    "oncookie": "on_the_cookie_box",
    "onramekin": "on_the_ramekin",
    "onstove": "on_the_stove",
    "oncabinet": "on_the_wooden_cabinet",
}
GOAL = {
    "open_middle": "open_the_middle_drawer_of_the_cabinet",
    "top_drawer_bowl": "open_the_top_drawer_and_put_the_bowl_inside",
    "push_plate": "push_the_plate_to_the_front_of_the_stove",
    "bowl_plate": "put_the_bowl_on_the_plate",
    "bowl_stove": "put_the_bowl_on_the_stove",
    "bowl_cabinet": "put_the_bowl_on_top_of_the_cabinet",
    "cheese_bowl": "put_the_cream_cheese_in_the_bowl",
    "wine_rack": "put_the_wine_bottle_on_the_rack",
    "wine_cabinet": "put_the_wine_bottle_on_top_of_the_cabinet",
    "stove_on": "turn_on_the_stove",
}
CAPBENCH = ("Lift", "Stack", "CubeRestack", "NutAssemblySquare")


def task_of(alias: str) -> tuple[str, str]:
    if "." not in alias:
        return ("capbench" if alias in CAPBENCH else "builtin"), alias
    kind, key = alias.split(".", 1)
    if kind in ("S", "ST"):
        return "liberopro", f"{PREFIX[kind]}{SPATIAL[key]}_and_place_it_on_the_plate"
    if kind in ("O", "OT"):
        return "liberopro", f"{PREFIX[kind]}{key}_and_place_it_in_the_basket"
    return "liberopro", PREFIX[kind] + GOAL[key]


def entries(source: Path, id_mark: str = "") -> list[dict]:
    """Corpus entries from a hand-written list (`alias | style | instruction` lines); ids are
    `<alias>.<style>.<id_mark>N`, numbered per alias and style."""
    out: list[dict] = []
    counts: dict[str, int] = {}
    for line in source.read_text().splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        alias, style, instruction = (p.strip() for p in line.split("|", 2))
        suite, task = task_of(alias)
        n = counts[f"{alias}.{style}"] = counts.get(f"{alias}.{style}", 0) + 1
        out.append(
            {
                "id": f"{alias}.{style}.{id_mark}{n}",
                "style": style,
                "suite": suite,
                "task": task,
                "expect": f"refuse:{style}" if style in REFUSALS else "goal",
                "instruction": instruction,
            }
        )
    return out


def main() -> None:
    halves: dict[str, list[dict]] = {"dev": [], "test": []}
    for entry in entries(HERE / "source.txt"):
        odd = hashlib.sha256(f"{entry['task']}|{entry['instruction']}".encode()).digest()[0] % 2
        halves["test" if odd else "dev"].append(entry)
    for name, half in halves.items():
        (HERE / f"{name}.yaml").write_text(yaml.safe_dump(half, sort_keys=False, width=200))
        print(name, len(half))


if __name__ == "__main__":
    main()
