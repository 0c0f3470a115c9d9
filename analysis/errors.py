"""Exceptions of the analysis package.

Every problem with an input (a run file, a metrics file, a table) is an `AnalysisError` whose message
names the file and what is wrong; the command line turns it into one line on stderr and exit code 2.
"""


class AnalysisError(Exception):
    """Base class: an input the analysis cannot use."""


class RunFormatError(AnalysisError):
    """A run file that is not a readable slidewave `run.h5` of a known `format_version`."""


class InputError(AnalysisError):
    """A metrics file, a table or a reference that is missing, malformed or inconsistent."""
