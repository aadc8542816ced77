// Wraps every function of the module so that a call fitting no signature raises a one-line
// TypeError naming what is wrong (bound last: it wraps the functions defined before it).
#include <pybind11/eval.h>

#include <string>
#include <vector>

#include "common.hpp"
#include "vibrofric/api/suggest.hpp"

namespace vibrofric::python {

void bind_one_line_calls(py::module_& m) {
  // A call that fits no signature (a misspelt or missing keyword, an extra argument) is one line
  // naming what is wrong, as the tool's flags, not pybind11's listing of the overloads: each
  // function is wrapped, and its parameters are read from its docstring's first line.
  m.def("_did_you_mean", [](const std::string& typed, const std::vector<std::string>& known) { return did_you_mean(typed, known); });
  py::exec(R"py(
import functools as _functools
import re as _re


def _one_line_calls(name):
    f = globals()[name]
    head = _re.match(r"\w+\((.*?)\)", f.__doc__ or "")
    params = [p.strip().lstrip("*").split("=")[0] for p in head.group(1).split(",")] if head else []
    params = [p for p in params if p]
    required = [p.strip() for p in head.group(1).split(",") if "=" not in p and p.strip() not in ("*", "")] if head else []

    @_functools.wraps(f)
    def call(*args, **kwargs):
        try:
            return f(*args, **kwargs)
        except TypeError as e:
            if "incompatible function arguments" not in str(e):
                raise
            for k in kwargs:
                if k not in params:
                    hint = _did_you_mean(k, params)
                    raise TypeError("%s() got an unexpected keyword argument '%s': expected %s%s"
                                    % (name, k, ", ".join(params), "; " + hint if hint else "")) from None
            given = set(required[:len(args)]) | set(kwargs)
            missing = [p for p in required if p not in given]
            if missing:
                raise TypeError("%s() missing %s: %s" % (name, "argument" if len(missing) == 1 else "arguments",
                                                         ", ".join(missing))) from None
            raise TypeError("%s() takes %s (%d positional given)" % (name, head.group(1) if head else "other arguments",
                                                                     len(args))) from None
    globals()[name] = call


for _name in ("samples", "fourier", "profile", "wave", "physical", "trace", "fit", "mu", "psi", "rig", "verify"):
    _one_line_calls(_name)
del _name
)py", m.attr("__dict__"));
}

}  // namespace vibrofric::python
