"""Shared fixtures: small random energies with a fixed seed, and bench/suite.py as a module."""

import importlib.util
import pathlib

import numpy as np
import pytest

SUITE = pathlib.Path(__file__).parents[2] / "bench/suite.py"


@pytest.fixture
def rng():
    return np.random.default_rng(20261124)


@pytest.fixture(scope="session")
def suite():
    """bench/suite.py, loaded as a module (it is a script, not part of the package)."""
    spec = importlib.util.spec_from_file_location("suite", SUITE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
