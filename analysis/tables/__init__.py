"""Tables of a sweep from its runs' metrics: Table 1 and its derived columns (`aggregate`), the
published reference, the comparison and CI ratchet, the scores of every celerity rule."""
