"""Boundary-element tools that regenerate linecontact's tables (not installed).

Roles, kept apart as in tamaas/ContactMechanics:

- :mod:`tools.bem.influence`  Love's influence coefficients of a rectangular cell.
- :mod:`tools.bem.halfspace`  the convolution operators (zero-padded DC-FFT, and its
  mirror-symmetric DCT form), with an FFT backend chosen by name.
- :mod:`tools.bem.solver`     the Polonsky-Keer contact solver and the flat-punch
  stiffness solver; unit-free.
- :mod:`tools.bem.cylinder`   drivers for the finite cylinder (paper sweep, adapted
  single depths).
- :mod:`tools.build_tables` writes tables/ .

tools/ may import linecontact; linecontact never imports tools/.
"""
