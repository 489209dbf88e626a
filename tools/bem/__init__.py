"""The boundary-element method: influence coefficients, half-space operators, the
contact solver and the cylinder, roller and tangential drivers (tools may import
linecontact, never the other way round)."""
