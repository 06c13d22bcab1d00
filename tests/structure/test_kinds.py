"""Tests of the kinds (structure.kinds): text enums behave as the strings they replace."""

from __future__ import annotations

import json
import pickle

import pytest

from structure.kinds import DyadKind, LoadKind, PairKind, TextEnum

TEXT_KINDS = [*DyadKind, *LoadKind]


@pytest.mark.parametrize("kind", TEXT_KINDS, ids=str)
def test_a_text_kind_behaves_as_its_string(kind: TextEnum):
    text = kind.value
    assert isinstance(kind, str)
    assert kind == text and text == kind
    assert (kind != text) is False
    assert str(kind) == text
    assert f"{kind}" == text
    assert f"[{kind:>9}]" == f"[{text:>9}]"
    assert "%s" % kind == text  # noqa: UP031 - the old formatting must agree too
    assert "{}".format(kind) == text  # noqa: UP032
    assert ", ".join([kind, kind]) == f"{text}, {text}"
    assert hash(kind) == hash(text)
    assert {text: 1}[kind] == 1 and {kind: 1}[text] == 1
    assert kind in {text} and text in {kind}
    assert kind in (text,) and text in (kind,)
    assert json.dumps(kind) == json.dumps(text)
    assert json.dumps({kind: [kind]}) == json.dumps({text: [text]})
    assert json.dumps({kind: [kind]}, indent=1) == json.dumps({text: [text]}, indent=1)
    assert sorted([kind, "0", "zzzzz"]) == sorted([text, "0", "zzzzz"])
    assert pickle.loads(pickle.dumps(kind)) is kind
    assert type(kind)(text) is kind


def test_dyad_kinds_are_the_five_dyads_read_either_way():
    assert [k.value for k in DyadKind] == ["RRR", "RRP", "RPR", "PRP", "RPP"]
    assert DyadKind.from_letters("PRR") is DyadKind.RRP
    assert DyadKind.from_letters("PPR") is DyadKind.RPP
    assert all(DyadKind.from_letters(k.value) is k for k in DyadKind)
    assert DyadKind.from_letters("PPP") is None


def test_load_kinds_know_their_statement():
    assert [k.value for k in LoadKind] == ["force", "moment", "mass", "gravity", "balance"]
    assert [k.n_values for k in LoadKind] == [2, 1, 2, 2, 1]
    assert [k.takes_point for k in LoadKind] == [True, False, True, False, True]
    assert [k.takes_link for k in LoadKind] == [True, True, True, False, True]
    assert LoadKind.MASS.usage == "mass LINK m J S"


def test_pair_kind_is_its_letter_like_the_other_kinds():
    """A driver's kind (R turns, P slides) is a PairKind and still reads as its letter."""
    assert PairKind.R == "R" and f"{PairKind.P}" == "P" and str(PairKind.H) == "H"
    assert PairKind("H").constraints == 1
    assert PairKind.R.constraints == 2
