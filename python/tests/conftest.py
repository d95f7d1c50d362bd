"""Shared paths and helpers of the cycleref Python tests."""

from __future__ import annotations

import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


def example(name: str) -> str:
    return (EXAMPLES / name).read_text(encoding="utf-8")


def cli_binary() -> pathlib.Path | None:
    """The `cycleref` command built by `cargo test` / `cargo build`, if there is one."""
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    for profile in ("debug", "release"):
        p = target / profile / "cycleref"
        if p.is_file():
            return p
    return None


@pytest.fixture
def m68x6() -> str:
    return example("gsk988-m68x6.nc")
