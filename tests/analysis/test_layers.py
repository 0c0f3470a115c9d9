"""The import rule of docs/architecture.md ("analysis: sub-packages and what may import what"):
each sub-package imports only itself and the sub-packages listed before it; `analysis.cli` (the
command line) may import all of them; nothing in analysis imports figures, paper or study. Checked
on every import statement, those inside functions included."""
import ast
from pathlib import Path

import pytest

ANALYSIS = Path(__file__).resolve().parents[2] / "analysis"
#: Lowest first: a sub-package may import the ones before it.
LAYERS = ("core", "theory", "fronts", "metrics", "tables", "confidence")


def imported_modules(path):
    """Every module named by an import statement of the file (relative imports resolved)."""
    package = ".".join(("analysis",) + path.relative_to(ANALYSIS).parent.parts)
    names = []
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            names += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                base = ".".join(package.split(".")[: len(package.split(".")) - node.level + 1] + ([base] if base else []))
            names += [f"{base}.{alias.name}" for alias in node.names] if base in ("analysis",) + tuple(
                f"analysis.{layer}" for layer in LAYERS) else [base]
    return names


def sub_package(module):
    parts = module.split(".")
    return parts[1] if len(parts) > 1 and parts[0] == "analysis" else None


MODULES = sorted(ANALYSIS.rglob("*.py"))


def test_every_module_lives_in_a_layer_or_is_the_entry():
    top = sorted(p.name for p in ANALYSIS.glob("*.py"))
    assert top == ["__init__.py", "__main__.py", "cli.py"]
    assert sorted(p.name for p in ANALYSIS.iterdir() if p.is_dir() and p.name != "__pycache__") == sorted(LAYERS)


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(ANALYSIS)))
def test_imports_follow_the_layers(path):
    own = path.relative_to(ANALYSIS).parts[0] if path.parent != ANALYSIS else None
    for module in imported_modules(path):
        root = module.split(".")[0]
        assert root not in ("figures", "paper", "study"), f"{path}: imports {module}"
        target = sub_package(module)
        if own is None or target is None or target == own:
            continue  # the entry (cli, __main__) may import every layer; a layer itself
        assert target in LAYERS, f"{path}: imports {module}, not in a sub-package"
        assert LAYERS.index(target) < LAYERS.index(own), (
            f"{path} ({own}) imports {module} ({target}): only {LAYERS[:LAYERS.index(own)]} may be imported")
