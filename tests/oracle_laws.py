"""Test-only normal laws with exact tangential and viscoelastic answers (not registered).

The generic tangential (Cattaneo-Mindlin through the MDR) and viscoelastic (Lee-Radok)
code takes any ContactModel; these two give it the shapes whose answers are known in
closed form: the Hertz sphere (Mindlin 1949, Mindlin & Deresiewicz 1953, Lee & Radok
1960) and the flat circular punch (linear law). Shared by test_tangential.py and
test_viscoelastic.py.
"""
import math

import numpy as np

from linecontact.models import ContactModel


class HertzSphere(ContactModel):
    """Rigid sphere of radius R = `radius` on a half-space, F = 4/3 E* sqrt(R) d^(3/2)
    (Hertz 1882; Johnson 1985, eq. 4.23)."""

    key = ""
    label = "Hertz sphere (test)"
    provenance = {"equation": "Hertz 1882; Johnson 1985, eq. 4.23"}

    def force(self, depth):
        return 4 / 3 * self.estar * math.sqrt(self.radius) * np.asarray(depth) ** 1.5

    def depth(self, force):
        return (3 * np.asarray(force) / (4 * self.estar * math.sqrt(self.radius))) ** (2 / 3)

    def stiffness(self, depth):
        return 2 * self.estar * np.sqrt(self.radius * np.asarray(depth))


class FlatPunch(ContactModel):
    """Rigid flat circular punch of radius a = `length`: F = 2 E* a d, linear in d
    (Boussinesq; Johnson 1985, section 3.8)."""

    key = ""
    label = "flat punch (test)"
    provenance = {"equation": "Boussinesq; Johnson 1985, section 3.8"}

    def force(self, depth):
        return 2 * self.estar * self.length * np.asarray(depth, dtype=float)

    def depth(self, force):
        return np.asarray(force, dtype=float) / (2 * self.estar * self.length)

    def stiffness(self, depth):
        return np.full(np.shape(depth), 2 * self.estar * self.length)
