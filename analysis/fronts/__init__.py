"""Slip fronts in a slip-velocity map: the edges of the slipping set, their tracks in time, the
celerity fit, the measurement rules that choose window and fronts, and the cross-correlation
estimate."""
