"""Elastic rings: the rings' (and seats') own deformation in the load distribution.

* :mod:`.section` — ring cross-sections estimated from the boundary dimensions, and their r–z meshes;
* :mod:`.axisymmetric` — axisymmetric finite elements with circumferential Fourier harmonics (scikit-fem);
* :mod:`.solid3d` — a full 3-D mesh of a ring, the reference for the harmonic model;
* :mod:`.influence` — influence coefficients of a ring at the ball positions (local Hertz part excluded),
  cached on disk;
* :mod:`.coupling` — Jones–Harris equilibrium with elastic rings.

Units: SI floats inside (m, N, Pa).  Method and validation: docs/rings.md.
"""
