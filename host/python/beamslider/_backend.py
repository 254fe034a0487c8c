"""One precision's extension module (beamslider._double or _float32) as the
classes see it (Backend), and the progress hook of long calls (Hook).
_bind.py binds the classes to a Backend.
"""

import numpy

from beamslider._errors import ArgumentError, CheckpointError, Error, RunError, SceneError


class Backend:
    """The ffi and lib of one extension module, and what is derived from them."""

    def __init__(self, module, name):
        self.ffi = ffi = module.ffi
        self.lib = lib = module.lib
        self.name = name
        if lib.bspy_build_check() != lib.BS_OK:
            raise ImportError("%s: the extension module was compiled against other headers than the library "
                              "it links (%s)" % (name, self.status_text(lib.BS_E_BUILD)))
        self.precision = ffi.string(lib.BS_REAL_NAME).decode()
        self.real = numpy.float32 if lib.bspy_real_is_float() else numpy.float64
        self.version = ffi.string(lib.bs_version()).decode()
        self.build_tag = int(lib.bspy_build_tag())
        self.checkpoint_size = int(lib.BS_CHECKPOINT_SIZE)
        self.max_modes = int(lib.BS_MAX_MODES)

        def missed(exception, value, traceback):
            """An exception that came before the Hook's own try (a
            KeyboardInterrupt is raised at the callback's first bytecode):
            given to the Hook, whose run then stops, instead of printed and
            lost by cffi."""
            frame = traceback.tb_frame if traceback is not None else None
            context = frame.f_locals.get("context") if frame is not None else None
            if context is not None:
                ffi.from_handle(context).fail(value)

        @ffi.def_extern(name="bspy_progress", onerror=missed)
        def progress(context, fraction, detail):
            ffi.from_handle(context)(fraction, ffi.string(detail).decode() if detail != ffi.NULL else None)

    def status_text(self, status):
        """The core's text of a bs_status."""
        return self.ffi.string(self.lib.bs_status_text(status)).decode()

    def host_error(self, status, error, result=None):
        """The exception of a failed host call (status, its bs_host_error)."""
        lib = self.lib
        text = self.ffi.string(error.text).decode("utf-8", "replace")
        if not text:
            text = self.ffi.string(lib.bs_host_status_text(status)).decode()
        if status == lib.BS_HOST_E_INPUT:
            return SceneError(text)
        if status == lib.BS_HOST_E_FAILED:
            core = getattr(result, "_core_status", None)
            return RunError(text, None if core in (None, lib.BS_OK) else self.status_text(core), result)
        if status == lib.BS_HOST_E_MEMORY:
            return MemoryError(text)
        return Error(text)

    def check(self, status, what):
        """Raises for a core status of a call that changes nothing on error."""
        lib = self.lib
        if status == lib.BS_OK:
            return
        text = "%s: %s" % (what, self.status_text(status))
        if status == lib.BS_E_ARGUMENT:
            raise ArgumentError(text)
        if status in (lib.BS_E_CHECKPOINT_SIZE, lib.BS_E_CHECKPOINT_DAMAGED, lib.BS_E_CHECKPOINT_BUILD,
                      lib.BS_E_CHECKPOINT_SCENE):
            raise CheckpointError(text)
        raise Error(text)

    def cstrings(self, texts):
        """A const char *const * of texts, and what keeps it alive."""
        keep = [self.ffi.new("char[]", text.encode()) for text in texts]
        return self.ffi.new("char *[]", keep or [self.ffi.NULL]), keep


class Hook:
    """The progress hook of a run, sweep, map or design: called by the library
    (through bspy_progress) a few times a second from the calling thread. It
    calls the user's callback(fraction, detail); an exception from it, or a
    KeyboardInterrupt delivered while Python code runs here, is kept and sets
    stop, which ends a run at its next row (the caller raises it)."""

    def __init__(self, backend, callback):
        self.callback = callback
        self.error = None
        self.stop = backend.ffi.new("int *")
        self.handle = backend.ffi.new_handle(self)

    def __call__(self, fraction, detail):
        if self.error is not None:
            return
        try:
            if self.callback is not None:
                self.callback(fraction, detail)
        except BaseException as error:  # noqa: B902 - handed back to the caller, KeyboardInterrupt too
            self.fail(error)

    def fail(self, error):
        """Keeps the first error and stops the run."""
        if self.error is None:
            self.error = error
        self.stop[0] = 1

    def raise_error(self):
        if self.error is not None:
            error, self.error = self.error, None
            raise error
