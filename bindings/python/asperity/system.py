# SPDX-License-Identifier: GPL-2.0-or-later
"""The System: substrate, topography, interaction and current state (asp_system)."""
import collections
import ctypes

from . import _constants as _c
from . import _names
from ._arrays import empty_field, field_pointer
from ._callbacks import Potential
from ._handles import OwnedHandle
from ._library import lib, check, read_string
from .errors import NullPointerError

__all__ = ["System"]

_SUBSTRATES = ("periodic", "free", "layer")

#: What :meth:`System.check_resolution` says: the interaction's cohesive zone over the pixel
#: size (0 when there is none, or none is known), whether the grid resolves it, and why.
Resolution = collections.namedtuple("Resolution", ["ratio", "resolved", "sentence"])


class System(OwnedHandle):
    """A contact problem on a grid: ``System(grid, contact_modulus, substrate="periodic")``.

    ``substrate`` is "periodic" (asp_system_create), "free" (asp_system_create_free: a
    non-periodic half-space loaded only inside the box; 2D grids only) or "layer"
    (asp_system_create_layer: a periodic elastic layer of the given ``thickness`` and
    ``poisson_ratio``, 0 <= nu < 0.5, bonded to a rigid base, whose K~(0) is its own,
    ``System(grid, E_star, substrate="layer", thickness=t, poisson_ratio=nu)``; the two
    keywords belong to the layer only). The system starts
    with zero pressure, the plain hard wall and no topography: a solve before
    :meth:`set_topography` (or assigning :attr:`topography`) raises InvalidStateError (for a
    flat surface, set zeros). A NaN or infinite height raises InvalidArgumentError naming its
    pixel (x, y). It holds a reference to
    its Grid (and the library keeps the C grid alive too).

    Fields (new NumPy arrays of shape (ny, nx) in C order, (nx,) in 1D, (local_ny, nx) on a
    grid distributed over MPI, whose arrays are the process's rows): :attr:`pressure`,
    :attr:`gap`, :attr:`displacement`, :attr:`contact` (the contact map),
    :attr:`topography` (settable from an array), or :meth:`get_field` with an optional ``out``
    array.
    Scalars: :meth:`get` by name ("mean_pressure", "contact_fraction", ...; see
    ``asperity.SCALARS``) or integer key, and a read-only property of each name
    (``system.mean_pressure``).
    Interactions: :meth:`set_hard_wall` (default), :meth:`set_adhesion`,
    :meth:`set_soft_wall`, :meth:`set_lennard_jones`, :meth:`set_potential`; whether the
    grid resolves them: :meth:`check_resolution`.
    """

    def __init__(self, grid, contact_modulus, substrate="periodic", thickness=None,
                 poisson_ratio=None):
        if substrate not in _SUBSTRATES:
            raise ValueError("substrate must be one of %s, got %r" % (_SUBSTRATES, substrate))
        handle = ctypes.c_void_p()
        if substrate == "layer":
            if thickness is None or poisson_ratio is None:
                raise ValueError('substrate="layer" needs thickness and poisson_ratio')
            function = "asp_system_create_layer"
            status = lib.asp_system_create_layer(grid.handle, float(contact_modulus),
                                                 float(poisson_ratio), float(thickness),
                                                 ctypes.byref(handle))
        else:
            if thickness is not None or poisson_ratio is not None:
                raise ValueError('thickness and poisson_ratio belong to substrate="layer" only')
            function = "asp_system_create" if substrate == "periodic" else "asp_system_create_free"
            status = getattr(lib, function)(grid.handle, float(contact_modulus),
                                            ctypes.byref(handle))
        check(status, function)
        self._handle = handle.value
        self._grid = grid
        self._substrate = substrate
        self._contact_modulus = float(contact_modulus)
        self._layer = (float(thickness), float(poisson_ratio)) if substrate == "layer" else None
        self._potential = None  # the Potential wrapper while a Python potential is set

    _destroy = lib.asp_system_destroy
    _what = "system"

    def _forget(self):
        """Drops the potential callback the handle kept alive."""
        self._potential = None

    @property
    def grid(self):
        """The Grid the system was made on."""
        return self._grid

    @property
    def substrate(self):
        """"periodic", "free" or "layer"."""
        return self._substrate

    @property
    def contact_modulus(self):
        """E* the system was created with."""
        return self._contact_modulus

    def _call(self, function, *args):
        """Calls lib.<function>(handle, *args); a failing Python potential is chained."""
        status = getattr(lib, function)(self.handle, *args)
        if status == _c.ASP_ERR_CALLBACK and self._potential is not None:
            message = lib.asp_last_error_message().decode("utf-8", "replace")
            self._potential.failure.raise_from(message, function)
        if self._potential is not None:
            self._potential.failure.take()
        check(status, function)

    # -- topography and interactions ---------------------------------------------------------
    def set_topography(self, heights):
        """Copies the heights (an array of the layout rules) and resets the state."""
        self._call("asp_system_set_topography", field_pointer(heights, self._grid, "heights"),
                   self._grid.local_pixels)

    def set_k0(self, k0):
        """The stiffness K~(0) > 0 of the mean mode (UnsupportedError on a free system)."""
        self._call("asp_system_set_k0", float(k0))

    def set_adhesion(self, work_of_adhesion, range):  # noqa: A002 - the header's name
        """Hard wall with exponential adhesion phi(g) = -w exp(-g/range)."""
        self._call("asp_system_set_adhesion", float(work_of_adhesion), float(range))
        self._potential = None

    def set_soft_wall(self, gamma_r, rho_r, gamma_a=0.0, rho_a=None):
        """phi(g) = gamma_r exp(-2g/rho_r) - gamma_a exp(-g/rho_a); rho_a defaults to rho_r."""
        self._call("asp_system_set_soft_wall", float(gamma_r), float(rho_r), float(gamma_a),
                   float(rho_r if rho_a is None else rho_a))
        self._potential = None

    def set_lennard_jones(self, work_of_adhesion, equilibrium_distance):
        """The Lennard-Jones 9-3 wall of work w and equilibrium distance z0."""
        self._call("asp_system_set_lennard_jones", float(work_of_adhesion),
                   float(equilibrium_distance))
        self._potential = None

    def set_hard_wall(self):
        """The plain, non-adhesive hard wall (the default)."""
        self._call("asp_system_set_hard_wall")
        self._potential = None

    def set_potential(self, fn, hard_wall=False):
        """A Python potential: ``fn(gap) -> (phi, dphi, d2phi or None)`` on NumPy arrays.

        ``gap`` is a read-only float64 array of the n = nx*ny gaps (flat, x fastest, in the
        system's units; on a distributed grid, the n = nx*local_ny of the process's rows); fn returns phi, phi' and phi'' at each (arrays of n values or
        scalars); d2phi may be None when the solver does not ask for it (it is asked for only
        by some solvers). ``hard_wall=False``: a soft wall (the unconstrained solvers);
        True: the hard wall g >= 0 with the potential on the open gap ("lbfgsb" on the gap).

        The system keeps fn alive until another interaction is set or the system is closed.
        An exception raised by fn ends the solve (or :meth:`get`) with
        :class:`asperity.CallbackError`, chained from it (``__cause__``); the system goes back
        to the state the solve started from and stays usable. fn must not use this system or
        the solver solving it.
        """
        potential = Potential(fn)
        self._call("asp_system_set_potential", potential.c_function, None,
                   1 if hard_wall else 0)
        self._potential = potential

    @property
    def potential(self):
        """The Python function set by set_potential (None for the built-in interactions)."""
        return None if self._potential is None else self._potential.fn

    def set_reference_pressure(self, reference_pressure):
        """The pressure solver errors are divided by (0: the library's default scale)."""
        self._call("asp_system_set_reference_pressure", float(reference_pressure))

    def reset(self):
        """Forgets the state (zero pressure): the next solve starts cold."""
        self._call("asp_system_reset")

    def check_resolution(self):
        """Whether the grid resolves the interaction (asp_system_check_resolution).

        Returns a :class:`Resolution` ``(ratio, resolved, sentence)``: the interaction's
        cohesive zone ``(pi/4) E* w/s^2`` (``(pi/4) E* rho^2/w`` for the exponential
        adhesion) over the smaller pixel size; ``resolved`` False when it is below one
        pixel, where the discrete problem has many metastable states (lattice trapping) and
        no solver can be expected to converge cleanly, and also for a Python potential,
        whose length is not known (``ratio`` 0); and a sentence saying what was compared.
        Asked before any solve: it reads the parameters only and calls no potential.
        """
        ratio = ctypes.c_double()
        resolved = ctypes.c_int()
        sentence = read_string("asp_system_check_resolution", self.handle,
                               ctypes.byref(ratio), ctypes.byref(resolved))
        return Resolution(ratio.value, resolved.value != 0, sentence)

    # -- results -----------------------------------------------------------------------------
    def get(self, key):
        """A scalar result by name ("mean_pressure", ...) or ASP_* key (asp_system_get)."""
        value = ctypes.c_double()
        self._call("asp_system_get", _names.resolve(_names.SCALAR, key, "key"),
                   ctypes.byref(value))
        return value.value

    def scalars(self):
        """Every scalar result the system has, as a dict (unsupported ones are left out)."""
        from .errors import UnsupportedError
        result = {}
        for name in _names.FAMILIES[_names.SCALAR]:
            try:
                result[name] = self.get(name)
            except UnsupportedError:
                pass
        return result

    def get_field(self, field, out=None):
        """A field by name ("pressure", "gap", "displacement", "topography", "contact") or
        ASP_FIELD_*.

        Returns a new (ny, nx) C-order array, or fills ``out`` (an array of the layout rules,
        writeable) and returns it.
        """
        code = _names.resolve(_names.FIELD, field, "field")
        if out is None:
            out = empty_field(self._grid)
        pointer = field_pointer(out, self._grid, "out", writeable=True)
        self._call("asp_system_get_field", code, pointer, self._grid.local_pixels)
        return out

    @property
    def pressure(self):
        """The pressure field (positive compressive), a new (ny, nx) array."""
        return self.get_field("pressure")

    @property
    def gap(self):
        """The gap field, a new (ny, nx) array."""
        return self.get_field("gap")

    @property
    def displacement(self):
        """The displacement field (positive into the body), a new (ny, nx) array."""
        return self.get_field("displacement")

    @property
    def contact(self):
        """The contact map, 1.0 in contact and 0.0 elsewhere, a new (ny, nx) array; its mean
        is contact_fraction."""
        return self.get_field("contact")

    @property
    def topography(self):
        """The heights, a new (ny, nx) array; assigning an array calls set_topography."""
        return self.get_field("topography")

    @topography.setter
    def topography(self, heights):
        self.set_topography(heights)

    def __repr__(self):
        if self._layer is not None:
            return "System(%r, %r, substrate='layer', thickness=%r, poisson_ratio=%r)" % (
                self._grid, self._contact_modulus, self._layer[0], self._layer[1])
        return "System(%r, %r, substrate=%r)" % (self._grid, self._contact_modulus,
                                                 self._substrate)


def _scalar_property(name):
    def getter(self):
        return self.get(name)
    getter.__name__ = name
    getter.__doc__ = "system.get(%r): the %s of the current state (asp_system_get)." % (
        name, name.replace("_", " "))
    return property(getter)


# A read-only property per scalar result of the header (mean_pressure, contact_fraction, ...).
for _name in _names.FAMILIES[_names.SCALAR]:
    if not hasattr(System, _name):
        setattr(System, _name, _scalar_property(_name))
del _name
