"""Closed forms, needed before a run exists: wave speeds and preload of the elastic layer, the
flutter wedge of steady sliding and its mode, Adams' supersonic slip wave, the generalized Rayleigh
wave and the stability of sliding on a deformable substrate."""
