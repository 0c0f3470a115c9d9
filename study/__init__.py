"""The slidewave study: sweep declarations, run configurations and run lengths (see README.md)."""
