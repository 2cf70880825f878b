import importlib.machinery
import importlib.util
import os
import sys

import pytest

# The package lives beside the scripts in contrib/.
sys.path.insert(0, os.path.abspath(os.path.join(os.path.dirname(__file__), "..")))


@pytest.fixture
def script():
    """A loader of contrib/'s scripts (files without .py) as modules:
    script("degree-study")."""
    def load(name):
        path = os.path.join(os.path.dirname(__file__), "..", name)
        loader = importlib.machinery.SourceFileLoader(name.replace("-", "_"), path)
        spec = importlib.util.spec_from_loader(loader.name, loader)
        module = importlib.util.module_from_spec(spec)
        loader.exec_module(module)
        return module
    return load
