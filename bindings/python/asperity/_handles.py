# SPDX-License-Identifier: GPL-2.0-or-later
"""Objects that own one library handle (Grid, System, Solver)."""
from . import _constants as _c
from .errors import NullPointerError


class OwnedHandle:
    """Owns one handle of the library: ``close()`` releases it once, as do garbage collection
    and the end of a ``with`` block. A subclass sets ``_destroy`` (the asp_*_destroy
    function, kept on the class so that it outlives the module at interpreter exit) and
    ``_what`` ("grid", ...), and may extend ``_forget()`` to drop what the handle kept alive."""

    _destroy = None
    _what = "object"
    _handle = None

    @property
    def handle(self):
        """The handle's address (an int); raises NullPointerError once closed."""
        if self._handle is None:
            raise NullPointerError(_c.ASP_ERR_NULL_POINTER, "the %s is closed" % self._what,
                                   type(self).__name__)
        return self._handle

    def _forget(self):
        """Drops what the handle kept alive (callbacks); called by close()."""

    def close(self):
        """Releases the handle (its asp_*_destroy function) and what it kept alive; a second
        call does nothing."""
        handle, self._handle = self._handle, None
        if handle is not None:
            type(self)._destroy(handle)
        self._forget()

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
