"""Every test, and every script a test starts as a command, imports the packages of this checkout
(analysis, study): the PYTHONPATH that the Snakefile and paper/Makefile set for the pipeline."""
import os
import sys

ROOT = os.path.dirname(os.path.abspath(__file__))
if ROOT not in sys.path:
    sys.path.insert(0, ROOT)
os.environ["PYTHONPATH"] = os.pathsep.join(filter(None, [ROOT, os.environ.get("PYTHONPATH")]))
