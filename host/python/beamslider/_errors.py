"""The exceptions of beamslider (docs/python.md, "Errors").

Every message is the text the `beamslider` command prints for the same
input (the library's, unchanged): file and line, or the override, the field,
the value and the allowed range. SceneError also carries them as attributes,
read from that text.
"""

import re


class Error(Exception):
    """Anything beamslider refuses or fails at."""


class SceneError(Error, ValueError):
    """A scene that cannot be read or built: a bad file, line, field, value or
    override (the library's BS_HOST_E_INPUT; `beamslider` exits 2).

    Attributes (None where the message has none): text, the whole message;
    file and line, where the bad line is; override, the "section.key=value"
    that was refused; field, "section.key"; allowed, the allowed range.
    """

    _where = re.compile(r"^(?P<file>[^:\n]+):(?P<line>\d+): ")
    _override = re.compile(r"^--set (?P<override>\S+): ")
    _field = re.compile(r"\[(?P<section>[A-Za-z0-9_]+)\] (?P<key>[A-Za-z0-9_]+)")

    def __init__(self, text):
        super().__init__(text)
        self.text = text
        where = self._where.match(text)
        override = self._override.match(text)
        field = self._field.search(text)
        self.file = where.group("file") if where else None
        self.line = int(where.group("line")) if where else None
        self.override = override.group("override") if override else None
        self.field = "%s.%s" % (field.group("section"), field.group("key")) if field else None
        self.allowed = text.split("allowed: ", 1)[1] if "allowed: " in text else None


class RunError(Error, RuntimeError):
    """Work that stopped: a step the core refused (the slider escaped, a value
    not finite), a progress callback that raised, a write that failed
    (BS_HOST_E_FAILED; `beamslider` exits 1).

    Attributes: text; status, the core's status text of the step that failed
    (None if none did); result, what was done up to there (a Run, a Trace or
    Estimates with the rows written, or None).
    """

    def __init__(self, text, status=None, result=None):
        super().__init__(text)
        self.text = text
        self.status = status
        self.result = result


class ArgumentError(Error, ValueError):
    """A call's argument out of its range (BS_E_ARGUMENT and its kind): the
    sim is unchanged."""


class CheckpointError(Error, ValueError):
    """A checkpoint restore() refuses: damaged, of another build or precision,
    or of another scene. The sim is unchanged."""
