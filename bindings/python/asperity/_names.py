# SPDX-License-Identifier: GPL-2.0-or-later
"""Names for the header's constants: families, nicer names and strings accepted by methods.

The header groups its integer constants in families by range: status codes 0..99, FFT
planning 1xx, normalisations 2xx, scalar results 3xx, fields 4xx, controls 5xx, history
columns 6xx, termination reasons 7xx, detrending modes 8xx, solver report keys 9xx. Each
family here is derived from the generated constants, so a constant added to the header gets
its names without an edit:

* the constant itself, ``ASP_CONTROL_PENETRATION`` (502);
* the nicer module-level name without ``ASP_``: ``CONTROL_PENETRATION``;
* the string accepted by methods: the name without ``ASP_`` and without the family's common
  prefix, in lower case: ``"penetration"`` (controls), ``"pressure"`` (fields), ``"error"``
  (history columns), ``"converged"`` (termination reasons), ``"plane"`` (detrending),
  ``"measure"`` (FFT planning), ``"rms_height"`` (normalisations), ``"mean_pressure"``
  (scalar results, whose names share no prefix), ``"iterations"`` (solver report keys). The name without ``ASP_`` alone is accepted
  as well: ``"control_penetration"``, ``"rms_height"`` (the same as ``"height"``).

Wherever a method takes one of these, it accepts the string, the integer constant, or any
int (passed through for the library to judge).
"""
from . import _constants as _c

_FAMILY_TITLES = {
    1: "FFT planning", 2: "normalisation", 3: "scalar result", 4: "field", 5: "control",
    6: "history column", 7: "termination reason", 8: "detrending mode",
    9: "solver report key",
}


def _families():
    families = {}
    for name, value in _c.HEADER_CONSTANTS.items():
        if _c.HEADER_OF[name] != "asperity.h" or not isinstance(value, int):
            continue
        if 100 <= value < 1000:
            families.setdefault(value // 100, {})[name] = value
    return families


def _short_names(constants):
    """ASP_CONTROL_MEAN_GAP -> mean_gap: strips ASP_ and the family's common word prefix."""
    words = [name[len("ASP_"):].split("_") for name in constants]
    common = 0
    if len(words) > 1:
        while all(len(w) > common + 1 and w[common] == words[0][common] for w in words):
            common += 1
    return {"_".join(w[common:]).lower(): value for w, value in zip(words, constants.values())}


#: family number (value // 100) -> {string name: integer value}
FAMILIES = {number: _short_names(constants) for number, constants in _families().items()}

_FULL_NAMES = {number: frozenset(constants) for number, constants in _families().items()}

#: family number -> {integer value: string name}
NAMES_OF = {number: {v: k for k, v in names.items()} for number, names in FAMILIES.items()}

(FFT_PLANNING, NORMALISATION, SCALAR, FIELD, CONTROL, HISTORY, TERMINATION, DETREND,
 REPORT) = range(1, 10)

#: The module-level names without ASP_ (CONTROL_PENETRATION = 502, ...), for every constant
#: of asperity.h. Status codes keep their ASP_ names only (OK and ERR_* are exported too).
NICE_CONSTANTS = {name[len("ASP_"):]: value for name, value in _c.HEADER_CONSTANTS.items()
                  if _c.HEADER_OF[name] == "asperity.h"}


def resolve(family, value, argument):
    """The integer code for ``value`` of the family: a string name, or an int passed through."""
    if isinstance(value, str):
        try:
            return FAMILIES[family][value.lower()]
        except KeyError:
            pass
        full = "ASP_" + value.upper()
        if full in _FULL_NAMES.get(family, ()):
            return _c.HEADER_CONSTANTS[full]
        from .errors import InvalidArgumentError
        raise InvalidArgumentError(
            _c.ASP_ERR_INVALID_ARGUMENT,
            "%s: unknown %s %r; expected one of %s" % (
                argument, _FAMILY_TITLES.get(family, "name"), value,
                ", ".join(repr(n) for n in FAMILIES[family])),
            "asperity (Python)")
    if isinstance(value, bool) or not isinstance(value, int):
        try:
            import numpy
            if isinstance(value, numpy.integer):
                return int(value)
        except ImportError:  # pragma: no cover
            pass
        from .errors import InvalidArgumentError
        raise InvalidArgumentError(
            _c.ASP_ERR_INVALID_ARGUMENT,
            "%s: expected a %s name (one of %s) or its integer constant, got %r" % (
                argument, _FAMILY_TITLES.get(family, "name"),
                ", ".join(repr(n) for n in FAMILIES[family]), value),
            "asperity (Python)")
    return int(value)


def name_of(family, value):
    """The string name of an integer code of the family (the int itself if unknown)."""
    return NAMES_OF[family].get(value, value)

