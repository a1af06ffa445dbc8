"""``json_text`` with ``indent`` writes what ``json.dumps`` writes, faster (its own writer
for dictionaries and lists of plain values)."""

from __future__ import annotations

import json
import math
import random

import pytest
import yaml
from conftest import ROOT

from haros_arch.model.load import from_data
from haros_arch.model.serialise import _SLOT, _finite, json_text, model_to_data

WORDS = ["", "a", "topic", "/ns/cmd_vel", "ünïcödé", "tab\there", "quote\"s", "back\\slash",
         "line\nbreak", "\x00nul", "\u2028", "emoji \U0001f916", "{[,]}:", _SLOT]
KEYS = ["", "k", "name", "ключ", "a\"b", "x\ny"]


def plain(rng: random.Random) -> object:
    choice = rng.randrange(8)
    if choice == 0:
        return rng.choice(WORDS)
    if choice == 1:
        return rng.randrange(-10**6, 10**6)
    if choice == 2:
        return rng.choice([0.0, -1.5, 1e-7, 3.141592653589793, 1e300, 2.5e-300])
    if choice == 3:
        return rng.choice([True, False, None])
    if choice == 4:
        return 10**30
    return rng.choice(WORDS[:4])


def nested(rng: random.Random, depth: int) -> object:
    if depth == 0 or rng.random() < 0.3:
        return plain(rng)
    kind = rng.randrange(4)
    size = rng.choice([0, 1, 2, 3, 5])
    if kind == 0:
        return [nested(rng, depth - 1) for _ in range(size)]
    if kind == 1:
        return tuple(nested(rng, depth - 1) for _ in range(size))
    return {rng.choice(KEYS) + str(i): nested(rng, depth - 1) for i in range(size)}


@pytest.mark.parametrize("seed", range(40))
@pytest.mark.parametrize("indent", [0, 1, 2, 4])
@pytest.mark.parametrize("ensure_ascii", [True, False])
def test_indented_text_is_json_dumps_text(seed, indent, ensure_ascii):
    rng = random.Random(seed)
    data = nested(rng, 6)
    assert json_text(data, indent=indent, ensure_ascii=ensure_ascii) == json.dumps(
        data, indent=indent, ensure_ascii=ensure_ascii, allow_nan=False)


def test_non_finite_numbers_and_keys_not_strings_are_written_as_before():
    data = {"a": [1.0, math.inf, {"b": -math.inf, "c": [math.nan]}], 1: {2.5: [True]},
            None: [], False: {"": {}}}
    expected = json.dumps(_finite(data), indent=2, allow_nan=False)
    assert json_text(data, indent=2) == expected
    assert '"Infinity"' in expected and '"NaN"' in expected and '"1": {' in expected


def test_values_that_are_not_plain_data_go_to_json_dumps():
    class Word(str):
        pass

    data = {"a": [Word("x"), {"b": 1}]}
    assert json_text(data, indent=2) == json.dumps(data, indent=2)
    with pytest.raises(TypeError):
        json_text({"a": [{1, 2}]}, indent=2)


def test_a_model_document_is_written_as_json_dumps_writes_it():
    model = from_data(yaml.safe_load((ROOT / "fixtures/queries/paper.yaml").read_text()))
    data = model_to_data(model)
    assert json_text(data, indent=2, ensure_ascii=False) == json.dumps(
        data, indent=2, ensure_ascii=False)
