"""Shared helpers of the Python tests: where the Rust-written fixtures are."""

import json
import pathlib

import pytest

FIXTURES = pathlib.Path(__file__).parent / "fixtures"


def load_fixture(name: str) -> dict:
    """A fixture written by `cargo test --test fixtures` (tests/fixtures.rs)."""
    with open(FIXTURES / name) as f:
        return json.load(f)


@pytest.fixture
def fixture_path():
    return FIXTURES
