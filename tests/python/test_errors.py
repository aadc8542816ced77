"""Bad input is ValueError with the library's one-line message naming the value; a solver failure is
vibrofric.SolverError (an ArithmeticError); a failure is never a NaN."""
import math

import numpy as np
import pytest

import vibrofric


def raises_value_error(fn, *args, names=(), **kw):
    with pytest.raises(ValueError) as info:
        fn(*args, **kw)
    msg = str(info.value)
    assert "\n" not in msg and msg.strip() == msg and msg
    for n in names:
        assert n in msg, (n, msg)
    return msg


def test_nan_and_infinite_beta_gamma():
    raises_value_error(vibrofric.mu, "sine", math.nan, 0.5, names=("beta", "nan"))
    raises_value_error(vibrofric.mu, "sine", 1.0, math.nan, names=("gamma", "nan"))
    raises_value_error(vibrofric.mu, "sine", math.inf, 0.5, names=("beta", "inf"))
    raises_value_error(vibrofric.psi, "sine", -math.inf, names=("beta", "-inf"))
    # one bad point fails the whole batch: no NaN in its place
    raises_value_error(vibrofric.mu, "sine", [1.0, math.nan, 2.0], 0.5, names=("beta",))


def test_threads_beyond_the_tools_limit():
    # the same limit as the tool's --threads (api/limits.hpp): 0 (every core) to 1024
    raises_value_error(vibrofric.mu, "sine", [1.0, 2.0], 0.5, threads=1025, names=("threads", "1025", "1024"))
    raises_value_error(vibrofric.mu, "sine", [1.0, 2.0], 0.5, threads=-1, names=("threads", "-1"))
    assert len(vibrofric.mu("sine", [1.0, 2.0], 0.5, threads=1024)) == 2


def test_beta_not_positive():
    raises_value_error(vibrofric.mu, "sine", 0.0, 0.5, names=("beta", "0"))
    raises_value_error(vibrofric.mu, "triangle", -1.5, 0.5, names=("beta", "-1.5"))
    raises_value_error(vibrofric.psi, "triangle", [1.0, -2.0], names=("beta", "-2"))
    raises_value_error(vibrofric.mu, "sine", "abc", 0.5, names=("beta", "abc"))


def test_gamma_without_contact():
    raises_value_error(vibrofric.mu, "sine", 1.0, -1.0, names=("gamma", "-1"))
    raises_value_error(vibrofric.mu, "square", 1.0, [0.0, -3.5], names=("gamma", "-3.5"))
    raises_value_error(vibrofric.mu, vibrofric.samples([0, 1, 4]), 1.0, -10.0, names=("gamma", "-10"))


def test_unknown_wave_profile_and_type():
    raises_value_error(vibrofric.mu, "sinus", 1.0, 0.5, names=("sinus",))
    raises_value_error(vibrofric.mu, "power:0.5", 1.0, 0.5, names=("0.5",))
    # A missing file is FileNotFoundError (an OSError), with the same one-line message.
    with pytest.raises(FileNotFoundError, match="/nonexistent/y.txt.*no such file"):
        vibrofric.mu("samples:/nonexistent/y.txt", 1.0, 0.5)
    with pytest.raises(FileNotFoundError, match="/nonexistent/p.txt"):
        vibrofric.mu("sine", 1.0, 0.5, profile="profile:/nonexistent/p.txt")
    raises_value_error(vibrofric.mu, "sine", 1.0, 0.5, profile="ball", names=("ball",))
    raises_value_error(vibrofric.mu, "sine", 1.0, 0.5, type="float", names=("type", "float"))
    with pytest.raises(TypeError):
        vibrofric.mu(3, 1.0, 0.5)
    with pytest.raises(TypeError):
        vibrofric.mu("sine", True, 0.5)


def test_bad_digits():
    raises_value_error(vibrofric.mu, "sine", 1.0, 0.5, digits=0, names=("digits", "0"))
    raises_value_error(vibrofric.mu, "sine", 1.0, 0.5, digits=10001, names=("digits", "10001"))
    raises_value_error(vibrofric.psi, "sine", 1.0, digits=-3, names=("digits", "-3"))
    raises_value_error(vibrofric.mu, "sine", 1.0, 0.5, digits=20, type="double", names=("digits", "double"))
    with pytest.raises(TypeError):
        vibrofric.mu("sine", 1.0, 0.5, digits=2.5)
    raises_value_error(vibrofric.verify, "eq17", digits=5, names=("digits", "5"))


def test_bad_arrays():
    raises_value_error(vibrofric.samples, [0.0, 1.0, math.nan, 2.0], names=("y[2]", "nan"))
    raises_value_error(vibrofric.samples, [0.0, 1.0, 2.0], t=[0.0, 1.0], names=("t", "y"))  # ragged
    raises_value_error(vibrofric.samples, [1.0, 1.0, 1.0], names=("constant",))
    raises_value_error(vibrofric.samples, [5.0], names=("sample",))
    raises_value_error(vibrofric.samples, [0.0, 1.0, 0.0, 1.0], names=("repeat",))
    raises_value_error(vibrofric.samples, [0.0, 1.0, 2.0], t=[0.0, 2.0, 1.0], names=("time", "increasing"))
    raises_value_error(vibrofric.samples, [0.0, 1.0, 2.0], t=[0.0, 1.0, 3.0], names=("end point", "not uniform"))
    raises_value_error(vibrofric.samples, np.zeros((2, 3)), names=("dimension",))
    raises_value_error(vibrofric.fourier, [0.1, 0.2], [1.0], names=("a", "b"))  # ragged
    raises_value_error(vibrofric.fourier, [0.1, math.inf], [1.0, 0.0], names=("a[1]", "inf"))
    raises_value_error(vibrofric.profile, [0.0, 1.0], [0.0], names=("r", "f"))
    raises_value_error(vibrofric.profile, [0.5, 1.0], [0.0, 1.0], names=("r = '0.5'",))
    # the scratch file the arrays go through is never named
    msg = raises_value_error(vibrofric.samples, [1.0, 1.0, 1.0])
    assert "vibrofric-array" not in msg and "/tmp" not in msg


def test_solver_failure_is_solver_error():
    assert issubclass(vibrofric.SolverError, ArithmeticError)
    assert not issubclass(vibrofric.SolverError, ValueError)
    # A root-finder budget of one iteration cannot locate the sine's stick onset (w' = beta).
    with pytest.raises(vibrofric.SolverError) as info:
        vibrofric.mu("sine", 1.0, 0.5, digits=30, max_iterations=1)
    assert "\n" not in str(info.value)
    with pytest.raises(ArithmeticError):
        vibrofric.mu("sine", [0.5, 1.0], 0.5, max_iterations=1)
    raises_value_error(vibrofric.mu, "sine", 1.0, 0.5, max_iterations=0, names=("max_iterations",))


def test_unknown_claim():
    raises_value_error(vibrofric.verify, "eq99", digits=10, names=("eq99",))


def test_a_call_that_fits_no_signature_is_one_line():
    # A misspelt keyword names itself, the parameters and the nearest one (as the tool's flags);
    # a missing argument is named; never pybind11's listing of the signatures.
    for call, words in ((lambda: vibrofric.mu("sine", 1, 0.2, digts=30), ["'digts'", "did you mean 'digits'?"]),
                        (lambda: vibrofric.physical("sine", E1=1, nu1=0.3, E2=1, nu2=0.3, v0=1, f=1, A=1, mu0=1,
                                                    u_mea=0), ["'u_mea'", "did you mean 'u_mean'?"]),
                        (lambda: vibrofric.samples([0, 1, 0, -1], period=2), ["'period'", "did you mean 'periods'?"]),
                        (lambda: vibrofric.mu("sine", 1), ["missing argument: gamma"]),
                        (lambda: vibrofric.physical("sine", nu1=0.3, E2=1, nu2=0.3, v0=1, f=1, A=1, mu0=1),
                         ["missing argument: E1"])):
        with pytest.raises(TypeError) as e:
            call()
        text = str(e.value)
        assert "\n" not in text and "incompatible" not in text, text
        for w in words:
            assert w in text, text
    assert vibrofric.mu.__doc__.startswith("mu(wave, beta, gamma")


@pytest.mark.parametrize("kw", [{}, {"digits": 20}, {"type": "long-double"}, {"strings": True}, {"threads": 2}])
def test_batches_name_the_failing_index_or_give_nan(kw):
    # mu and psi over arrays: the first failing element's error with its index (as numpy writes
    # it), or with nan_on_error=True NaN (None in object arrays) there and every other element the
    # scalar call's value.
    betas, gammas = np.array([1.0, 2.0, 0.5]), np.array([[0.2], [-3.0]])
    with pytest.raises(ValueError, match=r"^at index \(1, 0\): gamma = -3 gives no contact"):
        vibrofric.mu("sine", betas, gammas, **kw)
    with pytest.raises(ValueError, match=r"^at index \(1,\): beta = -1"):
        vibrofric.psi("sine", [1.0, -1.0, 2.0], **kw)
    got = vibrofric.mu("sine", betas, gammas, nan_on_error=True, **kw)
    assert got.shape == (2, 3)
    for j, b in enumerate(betas):
        assert got[0, j] == vibrofric.mu("sine", b, 0.2, **kw)
        assert got[1, j] is None if got.dtype == object else math.isnan(got[1, j])
    psi = vibrofric.psi("sine", [1.0, -1.0, 2.0], nan_on_error=True, **kw)
    assert psi[0] == vibrofric.psi("sine", 1.0, **kw) and psi[2] == vibrofric.psi("sine", 2.0, **kw)
    assert psi[1] is None if psi.dtype == object else math.isnan(psi[1])
    with pytest.raises(ValueError, match=r"^gamma = -3 gives no contact"):  # a scalar call: no index
        vibrofric.mu("sine", 1.0, -3.0, **kw)
