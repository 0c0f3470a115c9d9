"""The metrics of one run: `measure.measure_run` and the metric families it combines (opening, T/N
inversion, pulses, regime, energy, dissipation, validity)."""
