"""Fuzz tests (issue 11): mutated fixtures and JSON forms, garbage, for the library and the CLI.

The library may only raise its own errors (:class:`MechanismError`) and never
returns NaN; the command line exits 0, 1 or 2, prints no traceback, and its
JSON parses with a strict parser. Bounded: about half a minute in all. Run it
bigger by hand with ``ASSUR_FUZZ_EXAMPLES=5000 python -m pytest tests/test_fuzz.py``.
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from kinematics import make_plan, solve_forces, solve_pose
from kinematics.cli.commands import main
from kinematics.results.serialization import forces_to_dict, state_to_dict
from structure import analyze, parse_edgelist
from structure.errors import MechanismError
from structure.readwrite.jsonformat import mechanism_from_json, mechanism_to_dict

FIXTURES = Path(__file__).resolve().parent.parent / "fixtures"
#: the fixtures small enough to solve quickly, as lists of lines
SOURCES = {
    path.name: path.read_text(encoding="utf-8").splitlines()
    for path in sorted(FIXTURES.glob("*.edges"))
    if path.stat().st_size < 4000
}
EXAMPLES = int(os.environ.get("ASSUR_FUZZ_EXAMPLES", "60"))

#: tokens that have broken readers before: huge, deep, non-finite, odd text
NASTY = [
    "1e308",
    "-1e308",
    "1e151",
    "1e150",
    "1e-320",
    "1e99999999",
    "1" * 5000,
    "-" * 3000 + "1",
    "(" * 2000 + "1" + ")" * 2000,
    "sqrt(" * 300 + "2" + ")" * 300,
    "nan",
    "inf",
    "-inf",
    "1/0",
    "sqrt(-1)",
    "0x10",
    "1e400*1e400",
    "",
    "=",
    "on=",
    "angle=",
    "angle=1e308",
    "z=1,0",
    "z=99999999999999999999999,1",
    "é",
    "\u202e",
    "\x00",
    "0",
    "-1",
    "gear",
    "R",
    "P",
    "H",
    "x" * 200,
    # options named like a pair's own fields (issue 22: '0 1 R a=b' was a TypeError)
    "a=b",
    "b=1",
    "point=x",
    "gear=1",
    "line_no=2",
    # names the edge list cannot write back, and control characters
    "a#b",
    "\x1b[2J",
    "\x9b",
]

_SETTINGS = settings(
    max_examples=EXAMPLES,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
    derandomize=EXAMPLES <= 200,
)


# ----------------------------------------------------------------------------- inputs
@st.composite
def mutated_lines(draw) -> list[str]:
    """A fixture's lines after a few deletions, duplications, swaps and nasty tokens."""
    lines = list(SOURCES[draw(st.sampled_from(sorted(SOURCES)))])
    for _ in range(draw(st.integers(1, 4))):
        if not lines:
            break
        i = draw(st.integers(0, len(lines) - 1))
        tokens = lines[i].split()
        action = draw(st.sampled_from(["del", "dup", "swap", "token", "drop", "twice", "move"]))
        if action == "del":
            del lines[i]
        elif action == "dup":
            lines.insert(i, lines[i])
        elif action == "swap":
            j = draw(st.integers(0, len(lines) - 1))
            lines[i], lines[j] = lines[j], lines[i]
        elif not tokens:
            continue
        else:
            k = draw(st.integers(0, len(tokens) - 1))
            if action == "token":
                tokens[k] = draw(st.sampled_from(NASTY) | st.text(max_size=8))
            elif action == "drop":
                del tokens[k]
            elif action == "twice":
                tokens.insert(k, tokens[k])
            else:
                tokens.append(tokens.pop(k))
            lines[i] = " ".join(tokens)
    return lines


_JSON_VALUES = st.sampled_from(
    [
        None,
        True,
        0,
        -1,
        1e308,
        10**400,
        "",
        "x",
        "1e99999999",
        "-" * 3000 + "1",
        [],
        {},
        [1],
        [1, 2, 3],
    ]
)


def _mutate_json(data, draw, depth=0):
    """``data`` with one value, key or type changed somewhere inside."""
    if isinstance(data, dict) and data and depth < 6:
        key = draw(st.sampled_from(sorted(data, key=str)))
        action = draw(st.sampled_from(["inner", "inner", "value", "delete", "rename"]))
        out = dict(data)
        if action == "inner":
            out[key] = _mutate_json(data[key], draw, depth + 1)
        elif action == "value":
            out[key] = draw(_JSON_VALUES)
        elif action == "delete":
            del out[key]
        else:
            out[str(key) + "_"] = out.pop(key)
        return out
    if isinstance(data, list) and data and depth < 6:
        i = draw(st.integers(0, len(data) - 1))
        action = draw(st.sampled_from(["inner", "inner", "value", "delete", "extra"]))
        out = list(data)
        if action == "inner":
            out[i] = _mutate_json(data[i], draw, depth + 1)
        elif action == "value":
            out[i] = draw(_JSON_VALUES)
        elif action == "delete":
            del out[i]
        else:
            out.append(draw(_JSON_VALUES))
        return out
    return draw(_JSON_VALUES)


@st.composite
def mutated_json(draw) -> str:
    """The JSON form of a fixture with a value, key or type changed (or cut short)."""
    name = draw(st.sampled_from(sorted(SOURCES)))
    data = mechanism_to_dict(parse_edgelist(SOURCES[name], source=name))
    text = json.dumps(_mutate_json(data, draw))
    if draw(st.integers(0, 9)) == 0:
        text = text[: draw(st.integers(0, len(text)))]
    return text


garbage = st.text(max_size=200) | st.binary(max_size=200).map(lambda b: b.decode("latin-1"))


# ----------------------------------------------------------------------------- checks
def _no_nan(data) -> None:
    text = json.dumps(data, allow_nan=True)
    assert "NaN" not in text and "Infinity" not in text, text[:300]


def _library(mechanism_text: list[str] | str, as_json: bool = False) -> None:
    """Read, analyze, plan, solve the pose and the forces: only MechanismError may come."""
    try:
        if as_json:
            mechanism = mechanism_from_json(mechanism_text, source="fuzz.json")
        else:
            mechanism = parse_edgelist(mechanism_text, source="fuzz.edges")
        report = analyze(mechanism)
        if not mechanism.points:
            return
        plan = make_plan(report)
        _no_nan(state_to_dict(solve_pose(plan)))
        if mechanism.loads:
            _no_nan(forces_to_dict(solve_forces(plan)))
    except MechanismError:
        pass


def _strict(constant: str):
    raise ValueError(f"non-standard JSON constant {constant}")


def _cli(tmp_path: Path, suffix: str, text: str, *command: str) -> None:
    """Run ``assur COMMAND FILE ...`` in-process: exit 0/1/2, no traceback, strict JSON."""
    path = tmp_path / f"fuzz{suffix}"
    path.write_text(text, encoding="utf-8", errors="surrogatepass")
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main([command[0], str(path), *command[1:]])
    assert code in (0, 1, 2), err.getvalue()[:2000]
    assert "Traceback" not in err.getvalue() and "internal error" not in err.getvalue()
    assert "Traceback" not in out.getvalue()
    for line in err.getvalue().splitlines():
        assert len(line) < 2000
    if "--json" in command and out.getvalue():
        json.loads(out.getvalue(), parse_constant=_strict)
    if code == 0 and "--json" not in command:
        assert "nan" not in out.getvalue().lower().split()


# ----------------------------------------------------------------------------- the tests
@_SETTINGS
@given(lines=mutated_lines())
def test_library_takes_mutated_edge_lists(lines):
    _library(lines)


@_SETTINGS
@given(text=mutated_json())
def test_library_takes_mutated_json(text):
    _library(text, as_json=True)


@_SETTINGS
@given(text=garbage)
def test_library_takes_garbage(text):
    _library(text.splitlines())
    _library(text, as_json=True)


COMMANDS = [
    ("classify", "--json"),
    ("classify",),
    ("kinematics", "--json"),
    ("forces", "--json"),
    ("forces",),
    ("sweep", "--steps", "12"),
    ("gears", "--json"),
]


@settings(_SETTINGS, max_examples=max(EXAMPLES // 2, 10))
@given(lines=mutated_lines(), command=st.sampled_from(COMMANDS))
def test_cli_takes_mutated_edge_lists(tmp_path_factory, lines, command):
    _cli(tmp_path_factory.mktemp("fuzz"), ".edges", "\n".join(lines) + "\n", *command)


@settings(_SETTINGS, max_examples=max(EXAMPLES // 3, 10))
@given(text=mutated_json(), command=st.sampled_from(COMMANDS))
def test_cli_takes_mutated_json(tmp_path_factory, text, command):
    _cli(tmp_path_factory.mktemp("fuzz"), ".json", text, *command)


# ------------------------------------------------------------ the examples, each
def _edges(*extra: str) -> list[str]:
    return [
        "driver 1 omega=10",
        "0 1 R A",
        "1 2 R B",
        "2 3 R C",
        "3 0 R D",
        "point A 0 0",
        "point B 0 0.1",
        "point C 0.4 0.1",
        "point D 0.3 -0.2",
        *extra,
    ]


@pytest.mark.parametrize(
    "token",
    ["(" * 5000 + "1" + ")" * 5000, "-" * 5000 + "1", "1e99999999", "1" * 10**6, "1e308"],
)
def test_huge_or_deep_numbers_are_named_errors(token):
    with pytest.raises(MechanismError) as info:
        parse_edgelist(_edges(f"point Z {token} 0"))
    assert len(str(info.value)) < 1000


def test_a_coordinate_whose_square_overflows_is_refused_with_its_reason():
    with pytest.raises(MechanismError, match=r"beyond ±1e\+150"):
        parse_edgelist([*_edges()[:-1], "point D 1e308 0"])


def test_json_integer_of_5000_digits_is_a_named_error():
    with pytest.raises(MechanismError, match="4300 digits"):
        mechanism_from_json('{"points": {"A": [1%s, 0]}}' % ("0" * 5000))


def test_json_nested_too_deep_is_a_named_error():
    with pytest.raises(MechanismError, match="nested too deeply"):
        mechanism_from_json("[" * 100000 + "]" * 100000)


@pytest.mark.parametrize("values", [[1], [1, 2, 3]])
def test_json_load_with_a_missing_or_extra_value_is_refused(values):
    data = {
        "drivers": ["1"],
        "pairs": [{"links": [0, 1], "kind": "R", "point": "A"}],
        "points": {"A": [0, 0]},
        "loads": [{"kind": "force", "link": "1", "point": "A", "values": values}],
    }
    with pytest.raises(MechanismError, match="expected 'force"):
        mechanism_from_json(json.dumps(data))


def test_json_reader_refuses_a_negative_mass_as_the_edge_list_does():
    data = mechanism_to_dict(parse_edgelist(_edges("point S 0.2 0.1 on=2")))
    data["loads"] = [{"kind": "mass", "link": "2", "point": "S", "values": [-1, 0.1]}]
    with pytest.raises(MechanismError, match="cannot be negative"):
        mechanism_from_json(json.dumps(data))
    with pytest.raises(MechanismError, match="cannot be negative"):
        parse_edgelist(_edges("point S 0.2 0.1 on=2", "mass 2 -1 0.1 S"))


@pytest.mark.parametrize("load", ["balance 1 Q angle=90", "mass 2 1 0.1 S2"])
def test_balance_or_mass_on_a_point_without_coordinates_is_a_named_error(load):
    plan = make_plan(analyze(parse_edgelist(_edges(load))))
    with pytest.raises(MechanismError, match="needs coordinates"):
        solve_forces(plan)


def test_a_20_mb_line_is_quoted_cut():
    with pytest.raises(MechanismError) as info:
        parse_edgelist(_edges("point Z 0 0 " + "x" * 20_000_000))
    assert len(str(info.value)) < 1000 and "…" in str(info.value)


def _run(*argv: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(list(argv))
    return code, out.getvalue(), err.getvalue()


def test_csv_to_a_missing_directory_is_a_named_error(tmp_path):
    code, _, err = _run(
        "sweep",
        str(FIXTURES / "fourbar.edges"),
        "--steps",
        "4",
        "--csv",
        str(tmp_path / "missing" / "x.csv"),
    )
    assert code == 1 and err.startswith("error: cannot write") and "Traceback" not in err


@pytest.mark.parametrize("eta", ["2", "0", "-0.5", "nan"])
def test_gears_efficiency_out_of_range_is_a_usage_error(eta):
    code, out, err = _run("gears", str(FIXTURES / "ch3_3_11_planetary.edges"), "--efficiency", eta)
    assert code == 2 and out == "" and "(0, 1]" in err and "Traceback" not in err


def test_a_closed_pipe_ends_quietly(monkeypatch):
    class Closed(io.StringIO):
        def write(self, text):
            raise BrokenPipeError(32, "Broken pipe")

    err = io.StringIO()
    with contextlib.redirect_stdout(Closed()), contextlib.redirect_stderr(err):
        code = main(["classify", str(FIXTURES / "fourbar.edges"), "--json"])
    assert code == 0 and err.getvalue() == ""


def test_a_bug_is_one_line_asking_to_report_it(monkeypatch):
    def broken(*args, **kwargs):
        raise KeyError("boom")

    monkeypatch.setattr("kinematics.cli.classify.analyze", broken)
    monkeypatch.delenv("ASSUR_DEBUG", raising=False)
    code, _, err = _run("classify", str(FIXTURES / "fourbar.edges"))
    assert code == 3 and len(err.splitlines()) == 1 and "report" in err
    assert "Traceback" not in err
    monkeypatch.setenv("ASSUR_DEBUG", "1")
    code, _, err = _run("classify", str(FIXTURES / "fourbar.edges"))
    assert code == 3 and "Traceback" in err


@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # the overflow is the point
def test_overflowing_loads_are_not_finite_errors_never_nan():
    lines = _edges("point S 0.2 0.1 on=2", "mass 2 1e150 1e150 S", "gravity 0 -1e150")
    lines[0] = "driver 1 omega=1e150"
    code, out, err = _run_file(lines, "forces", "--json")
    assert code == 1 and "not finite" in err
    json.loads(out, parse_constant=_strict)


def _run_file(lines: list[str], command: str, *options: str) -> tuple[int, str, str]:
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "m.edges"
        path.write_text("\n".join(lines) + "\n", encoding="utf-8")
        return _run(command, str(path), *options)


def test_import_structure_does_not_import_sympy():
    code = "import structure, sys; print('sympy' in sys.modules)"
    result = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        check=True,
        cwd=Path(__file__).resolve().parent.parent,
    )
    assert result.stdout.strip() == "False"


@pytest.mark.parametrize(
    "line",
    ["0 1 R A " + "x" * 20_000_000, "x" * 20_000_000 + " 5 R Q", "driver " + "x" * 20_000_000],
)
def test_the_cli_quotes_a_20_mb_line_cut(line):
    code, out, err = _run_file([*_edges(), line], "classify")
    assert code == 1 and out == "" and len(err) < 2000 and "…" in err


def test_fuzz_finding_a_mesh_without_either_tooth_number_is_a_named_error():
    """Found by the fuzz test (5,000 cases): a TypeError in the coaxiality of the planets."""
    lines = [
        "ground 0",
        "driver C",
        "0 C R O",
        "0 1 R O",
        "C 2 R B",
        "1 2 H gear module=0.02",
        "2 0 H gear z=20,60 internal=0 module=0.02",
        "moment 1 20",
    ]
    code, out, err = _run_file(lines, "gears", "--json")
    assert code == 1 and "neither tooth number" in err
    assert "neither tooth number" in json.loads(out, parse_constant=_strict)["error"]
