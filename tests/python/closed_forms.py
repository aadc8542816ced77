"""Closed forms of the paper, exact in rationals (fractions.Fraction), for the Python module's tests.

Each takes beta and gamma as the decimal numbers the module reads from a float argument: the
shortest text that reads back to the float (repr), so beta = 0.1 means the decimal 0.1.
"""
from decimal import Decimal, ROUND_HALF_EVEN, localcontext
from fractions import Fraction


def exact(x):
    """The decimal that the module reads for x: floats by repr, strings as written."""
    return Fraction(repr(x)) if isinstance(x, float) else Fraction(str(x))


def mu_triangle(beta, gamma):
    """Eq. 19: mu_tri = 2 beta/(4 + beta) for -1 < gamma <= 1 (and, by Eq. 18, the same for the
    unclipped wave); no stick-slip (mu = 1) from beta_c = 4 on (Eq. 6)."""
    b = exact(beta)
    assert -1 < exact(gamma) <= 1
    return Fraction(1) if b >= 4 else 2 * b / (4 + b)


def mu_square(beta, gamma):
    """Eq. 22: beta/(4(1 + gamma)) for beta < 2(1 + gamma), else 1 - (1 + gamma)/beta."""
    b, g = exact(beta), exact(gamma)
    assert -1 < g <= 1
    return b / (4 * (1 + g)) if b < 2 * (1 + g) else 1 - (1 + g) / b


def mu_sawtooth_right(beta, gamma):
    """Eq. 19: mu_str = beta/2 in the jumping range, 1 from beta_c = 2 on."""
    b = exact(beta)
    assert -1 < exact(gamma) <= 1
    return Fraction(1) if b >= 2 else b / 2


def mu_sawtooth_left(beta, gamma):
    """Eq. 19: mu_stl = beta/(2 + beta) in the jumping range."""
    b = exact(beta)
    assert -1 < exact(gamma) <= 1
    return b / (2 + b)


def psi_triangle(beta):
    """Eq. 17: Psi_tri = (4 - beta)/(4 + beta), 0 from beta_c = 4 on."""
    b = exact(beta)
    return Fraction(0) if b >= 4 else (4 - b) / (4 + b)


def psi_sawtooth_right(beta):
    """Eq. 17: Psi_str = 1 - beta/2, 0 from beta_c = 2 on."""
    b = exact(beta)
    return Fraction(0) if b >= 2 else 1 - b / 2


def psi_sawtooth_left(beta):
    """Eq. 17: Psi_stl = 2/(2 + beta)."""
    return 2 / (2 + exact(beta))


def nearest_double(q):
    """The double nearest to the rational q (int / int true division is correctly rounded)."""
    return q.numerator / q.denominator


def rounded(q, digits):
    """q correctly rounded to `digits` significant digits, as a Decimal."""
    with localcontext() as ctx:
        ctx.prec = digits
        ctx.rounding = ROUND_HALF_EVEN
        return Decimal(q.numerator) / Decimal(q.denominator)
