"""A crowned roller's tangential law by direction (Contact.tangential, method "mindlin",
the default for a circular crown): its k_t against Mindlin's closed form for the Hertz
ellipse (linecontact.mindlin), its partial-slip law, the loads at which the ellipse
reaches the roller's ends, and the refusals."""
import numpy as np
import pytest

from linecontact import mindlin
from linecontact.contact import Contact, Convex, Elastic, Roller
from linecontact.errors import CombinationError, UnknownNameError
from linecontact.hertz import hertz_contact

STEEL = Elastic(210e9, 0.3)


def _issue_roller(n_slices=None):
    """R 10 mm, L 20 mm, crown radius 500 mm, steel on steel (issue 32)."""
    return Contact(Roller(10e-3, 20e-3, crown_radius=0.5), None, STEEL, STEEL,
                   n_slices=n_slices)


@pytest.mark.parametrize("n_slices", [20, 40, 80])
def test_issue_roller_kt_by_direction_is_mindlins(n_slices):
    """At 1 kN the crowned roller's k_t is 192.5 N/um across and 161.9 N/um along
    (Mindlin's ellipse; issue 32: within 1 %). It is the slices' k_n times Mindlin's
    ratio, so it differs from the closed form by the slices' error in k_n: measured
    4.9e-4 at 20 slices, 7e-5 at 40, 3e-5 at 80; asserted 1e-3."""
    c = _issue_roller(n_slices)
    h = hertz_contact(1e3, 0.5, 0.01, c.estar)
    for direction, axis, value in (("across", "y", 192.5e6), ("along", "x", 161.9e6)):
        t = c.tangential(0.1, force=1e3, direction=direction)
        assert (t.method, t.direction, t.notes) == ("mindlin", direction, ())
        closed = mindlin.full_stick_stiffness(h.a, h.b, c.gstar, c.estar, axis)
        assert t.stiffness == pytest.approx(closed, rel=1e-3)
        assert t.stiffness == pytest.approx(value, rel=1e-2)
    assert c.tangential(0.1, force=1e3).direction == "across", "the default direction"


def test_partial_slip_is_mindlins_law():
    """Under Q the shift is Mindlin's 3 mu P/(2 k_t) [1 - (1 - Q/mu P)^(2/3)] of the
    ellipse (to the slices' error in the normal law, 1e-3 asserted), the force at that
    shift returns Q (rtol 1e-9: the inverse of the same law), and u* = 3 mu P/(2 k_t)."""
    c = _issue_roller(40)
    mu, P = 0.12, 1e3
    Q = np.array([0.1, 0.5, 0.9]) * mu * P
    for direction in ("across", "along"):
        t = c.tangential(mu, force=P, tangential_force=Q, direction=direction)
        ref = mindlin.EllipticalTangentialContact(
            P, 0.5, 0.01, c.estar, c.gstar, mu,
            direction="y" if direction == "across" else "x")
        assert t.shift == pytest.approx(ref.shift(Q), rel=1e-3)
        assert t.gross_slip_shift == pytest.approx(ref.gross_slip_shift, rel=1e-3)
        back = c.tangential(mu, force=P, shift=t.shift, direction=direction)
        assert back.tangential_force == pytest.approx(Q, rel=1e-9)


def test_ellipse_reaching_the_ends_falls_back_with_a_note():
    """At 100 kN the Hertz ellipse of the issue's roller (a = 10.6 mm > L/2 = 10 mm)
    reaches the ends: the equivalent ellipse of the slices' footprint is used there
    (its half-length L/2 and the slices' k_n; linecontact.mindlin.
    equivalent_ellipse_ratio), and the notes say so; the 1 kN load in the same call
    keeps Mindlin's ratio."""
    c = _issue_roller(40)
    F = np.array([1e3, 1e5])
    assert hertz_contact(1e5, 0.5, 0.01, c.estar).a > 10e-3
    t = c.tangential(0.1, force=F)
    ratio = mindlin.stiffness_ratio(0.5, 0.01, c.gstar, c.estar, "y")
    s = t.normal.solutions[1]
    ell = mindlin.equivalent_ellipse_ratio(0.5 * s.contact_length,
                                           s.stiffness_matrix[0, 0], c.gstar, c.estar,
                                           "y")
    assert t.stiffness_ratio == pytest.approx([ratio, ell], rel=1e-15)
    assert "reaches the roller's ends" in t.notes[0]
    assert any("equivalent ellipse across" in n for n in t.notes[1:])


def test_cam_follower_gets_mindlins_stiffness_against_its_cam():
    """The crowned cam follower (R 8 mm, L 12 mm, Rc 300 mm on a 25 mm cam, steel, 2 kN):
    the ellipse's radii are Rc along the axis and the effective radius across; k_t is
    Mindlin's for those (rtol 1e-3), across stiffer than along."""
    c = Contact(Roller(8e-3, 12e-3, crown_radius=0.3), Convex(25e-3), STEEL, STEEL,
                n_slices=40)
    h = hertz_contact(2e3, 0.3, c.radius, c.estar)
    across = c.tangential(0.15, force=2e3).stiffness
    along = c.tangential(0.15, force=2e3, direction="along").stiffness
    assert across == pytest.approx(mindlin.full_stick_stiffness(h.a, h.b, c.gstar, c.estar,
                                                                "y"), rel=1e-3)
    assert along == pytest.approx(mindlin.full_stick_stiffness(h.a, h.b, c.gstar, c.estar,
                                                               "x"), rel=1e-3)
    assert across > along


def test_other_contacts_keep_the_mdr_and_refuse_mindlin():
    """A straight roller's default stays the MDR (no direction); method="mindlin" on it
    is refused, as is an unknown direction."""
    c = Contact(Roller(5e-3, 10e-3), None, STEEL, STEEL)
    t = c.tangential(0.1, force=1e3)
    assert (t.method, t.direction) == ("mdr", None)
    with pytest.raises(CombinationError, match="crowned roller"):
        c.tangential(0.1, force=1e3, method="mindlin")
    with pytest.raises(UnknownNameError, match="direction"):
        _issue_roller(20).tangential(0.1, force=1e3, direction="sideways")


def test_mdr_law_says_its_measured_error_or_that_it_has_none():
    """The MDR's direction-free ratio carries a note: for a crowned roller its
    difference from Mindlin's ellipse (issue 32's roller: -8.6 % across, +8.6 % along),
    for a straight cylinder's law its difference from the BEM table (where the table
    covers the case), for another profile its difference from the equivalent ellipse
    (stiffer across, softer along than the MDR's ratio)."""
    c = _issue_roller(20)
    (note,) = c.tangential(0.1, force=1e3, method="mdr").notes
    assert "-8.6% from Mindlin's Hertz ellipse across, +8.6% along" in note
    (note,) = Contact(Roller(5e-3, 10e-3, profile="iso16281"), None, STEEL, STEEL,
                      n_slices=20).tangential(0.1, force=1e3, method="mdr").notes
    assert "from the equivalent ellipse of the footprint across" in note
    assert note.split(":")[2].strip().startswith("-")       # MDR below it across
    (note,) = Contact(Roller(5e-3, 10e-3), None, STEEL, STEEL).tangential(
        0.1, force=1e3).notes
    assert "BEM" in note
