"""What WordNet says about two nouns: the same thing, one a more general word for the other, or two distinct kinds of
one close class ("mug" and "cup" are both drinking vessels; "cheddar" and "cream cheese" both cheeses). Read from the
compact lexicon `build.py` writes (WordNet 3.1 nouns; licence in WORDNET_LICENSE), loaded once per process."""

from __future__ import annotations

import functools
import gzip
import json
from dataclasses import dataclass
from pathlib import Path

from lemminflect import getAllLemmas

LEXICON_PATH = Path(__file__).with_name("nouns.json.gz")
# Lexicographer files of things one can see and hold: only senses of these count when naming objects (a "cup" is
# also a quantity, a "plate" a dental plate and a baseball base; those are artifacts too, and count)
PHYSICAL = frozenset(["noun.artifact", "noun.food", "noun.object", "noun.plant", "noun.substance", "noun.body"])
# Lexicographer files of nothing one sets on a table: people, groups, acts, times, feelings, ideas, amounts. Files
# left out keep a word a possible thing (a "letter" is filed under communication, "money" under possession, a
# "zone" under location: each can be what a request names).
NOT_THINGS = frozenset(
    ["noun.act", "noun.attribute", "noun.cognition", "noun.event", "noun.feeling", "noun.group", "noun.motive"]
    + ["noun.person", "noun.phenomenon", "noun.process", "noun.relation", "noun.state", "noun.time", "noun.quantity"]
)


@dataclass(frozen=True)
class Kinship:
    """How two nouns' physical senses relate: `a` and `b` share a sense (`same`), some sense of `a` is a class some
    sense of `b` falls under (`broader`: "vessel" for a bowl) or the other way round (`narrower`: "mallet" for a
    hammer); else `shared` is the deepest class some senses of both fall under, `shared_depth` its depth (edges from
    `entity`): two kinds of one close class ("mug" and "cup": container, 6) or of nothing closer than "artifact"."""

    same: bool = False
    broader: bool = False
    narrower: bool = False
    shared_depth: int = 0
    shared: str = ""

    @property
    def related(self) -> bool:
        return self.same or self.broader or self.narrower


class Nouns:
    def __init__(self, path: Path = LEXICON_PATH):
        with gzip.open(path, "rb") as f:
            data = json.loads(f.read())
        self._lexnames: list[str] = data["lexnames"]
        self._synsets: list[list] = data["synsets"]
        self._lemmas: dict[str, list[int]] = data["lemmas"]
        self._name: dict[int, str] = {}
        for lemma, ids in self._lemmas.items():  # a synset's first lemma in file order names it in messages
            for i in ids:
                self._name.setdefault(i, lemma)

    def senses(self, noun: str) -> list[int]:
        """The physical senses of `noun` (or of its singular), in WordNet's order; [] for a word it does not file
        as a thing."""
        word = noun.lower().strip()
        forms = [word] + [f for f in getAllLemmas(word).get("NOUN", ()) if f != word]
        for form in forms:
            ids = [i for i in self._lemmas.get(form, []) if self._lexnames[self._synsets[i][0]] in PHYSICAL]
            if ids:
                return ids
        return []

    def names_no_thing(self, noun: str) -> bool:
        """WordNet files `noun` (or its singular) and every sense of it under `NOT_THINGS`: "grandma", "folks",
        "crowd" name no thing to look for. False for a word it does not file ("lol") and for a word with any sense
        that may be a thing ("deck", "step", "letter")."""
        word = noun.lower().strip()
        for form in [word] + [f for f in getAllLemmas(word).get("NOUN", ()) if f != word]:
            ids = self._lemmas.get(form)
            if ids:
                return all(self._lexnames[self._synsets[i][0]] in NOT_THINGS for i in ids)
        return False

    @functools.lru_cache(maxsize=65536)  # noqa: B019 - one lexicon per process, shared
    def ancestors(self, synset: int) -> dict[int, int]:
        """synset -> its distance up from `synset` (itself 0), over class and instance hypernyms."""
        out = {synset: 0}
        frontier = [synset]
        while frontier:
            nxt = []
            for s in frontier:
                for h in self._synsets[s][1]:
                    if h not in out:
                        out[h] = out[s] + 1
                        nxt.append(h)
            frontier = nxt
        return out

    @functools.lru_cache(maxsize=65536)  # noqa: B019
    def depth(self, synset: int) -> int:
        """Edges from the root on the shortest hypernym path."""
        hyps = self._synsets[synset][1]
        return 0 if not hyps else 1 + min(self.depth(h) for h in hyps)

    def kinship(self, a: str, b: str) -> Kinship | None:
        """None when WordNet does not file both as things; else how `a` stands to `b` (`Kinship`)."""
        sa, sb = self.senses(a), self.senses(b)
        if not sa or not sb:
            return None
        same = bool(set(sa) & set(sb))
        broader = any(x in self.ancestors(y) for x in sa for y in sb if x != y)
        narrower = any(y in self.ancestors(x) for x in sa for y in sb if x != y)
        if same or broader or narrower:
            return Kinship(same, broader, narrower)
        best = (0, -1)
        for x in sa:
            for y in sb:
                for c in self.ancestors(x).keys() & self.ancestors(y).keys():
                    best = max(best, (self.depth(c), c))
        return Kinship(shared_depth=best[0], shared=self._name.get(best[1], ""))


@functools.cache
def nouns() -> Nouns:
    """The process's lexicon (about 0.5 s to load)."""
    return Nouns()
