"""The README's commands name files that are shipped (issue 22, item 21)."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text(encoding="utf-8")


def test_every_bundled_file_the_readme_names_exists():
    named = set(re.findall(r"\b((?:fixtures|docs|benchmarks)/[\w./-]*\w)", README))
    assert len(named) > 10, named
    missing = sorted(path for path in named if not (ROOT / path).exists())
    assert not missing, f"the README names files that are not shipped: {missing}"


def test_the_readme_has_exactly_two_set_up_commands():
    section = README.split("## Set up", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```\n(.*?)```", section, flags=re.S)
    assert len(blocks) == 2, blocks
    assert "pip install" in blocks[0] and "assur " in blocks[0]
    assert ".[test]" in blocks[1] and "python -m pytest" in blocks[1]
