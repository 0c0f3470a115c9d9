"""slidewave analysis: from a run's HDF5 to metrics, Table 1 and the check against the paper.

Pure functions in one module per concept (see analysis/README.md); `python3 -m analysis --help`
lists the commands. `analysis.core.io` is the only module that reads HDF5.
"""
