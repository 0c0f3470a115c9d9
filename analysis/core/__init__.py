"""Plumbing every other sub-package uses: the run-file reader (`io`, the one h5py user), input
errors, atomic file writes and the CSV table format."""
