"""The one exception of the Python side for an input it cannot use.

Every problem with an input (a run file, a metrics file, a table, a reference, a command-line value)
is an `InputError` whose message names the file (or option) and what is wrong; each command line
(analysis, figures, paper) turns it into one line on stderr and a non-zero exit code, and writes no
output file.
"""


class InputError(Exception):
    """An input that is missing, unreadable, malformed, of an unknown format or out of range."""

