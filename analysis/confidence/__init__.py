"""How sure the study is: seed ensembles, method envelopes, mesh and time-step limits, the Fig. 3
timeline across seeds and meshes, pulse counts across seeds."""
