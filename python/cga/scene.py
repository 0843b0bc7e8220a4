"""Scenes built in code: ``cga.Scene()`` takes the camera, settings, lights, materials and
every object kind of the scene format (docs/SCENES.md), field for field under the format's
own names, and renders through the same loader and pipeline as a scene file, so it gets the
same checks, messages and pictures. Loops, variables and functions are Python's:

    >>> import cga
    >>> scene = cga.Scene().camera(position=[0.0, -8.0, 2.0], look_at=[0.0, 0.0, 0.5], width=32, height=24)
    >>> scene = scene.light(position=[-4.0, -6.0, 8.0])
    >>> for k in range(3):
    ...     scene = scene.sphere(centre=[k - 1.0, 0.0, 0.5], radius=0.4, material={"colour": [0.9, 0.2, 0.1]})
    >>> picture = scene.render(spp=1)
    >>> picture.srgb.shape
    (24, 32, 3)

``Scene.load(path)`` and ``Scene.parse(text)`` read a scene file as before; ``scene.toml()``
is the text a built scene is read from (an error's line and column count in it).
"""

import math
import re

from . import _cga

#: The object kinds of the scene format, each a method of :class:`Scene`.
# The format's own registry: each kind and the fields it takes beyond the common ones.
FIELDS = dict(_cga._object_kinds())
KINDS = list(FIELDS)

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k):
    return k if _BARE.match(k) else _string(k)


def _string(s):
    out = ['"']
    for ch in s:
        if ch in '"\\':
            out.append("\\" + ch)
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    return "".join(out) + '"'


def _value(v):
    """A Python value as TOML: numbers (numpy's too), strings, lists, arrays and dicts."""
    if hasattr(v, "tolist") and not isinstance(v, (str, bytes)):
        # numpy arrays and scalars, as the Python values they hold.
        return _value(v.tolist())
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        x = float(v)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_key(str(k))} = {_value(x)}" for k, x in v.items()) + " }"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    raise TypeError(f"a scene field takes numbers, strings, lists, arrays and dicts, not {type(v).__name__}")


def _table(header, fields):
    return header + "\n" + "".join(f"{_key(k)} = {_value(v)}\n" for k, v in fields.items() if v is not None)


class Scene:
    """A scene built in code (see the module's text); every method returns the scene, so
    calls chain. Fields are the scene format's, under its names; what they must be is
    checked when the scene is rendered or built, with the format's messages."""

    def __init__(self):
        self._camera, self._render, self._environment = {}, {}, None
        self._lights, self._materials, self._objects = [], {}, []

    # Reading scene files, as cga._cga.Scene does.
    @staticmethod
    def load(path):
        """A scene file, checked (``cga.SceneError`` naming file, line and field)."""
        return _cga.Scene.load(path)

    @staticmethod
    def parse(text, file="scene.toml"):
        """A scene given as text, checked; ``file`` names it in errors."""
        return _cga.Scene.parse(text, file)

    def camera(self, **fields):
        """The ``[camera]`` table: ``position``, ``look_at``, ``fov``, ``width``, …"""
        self._camera.update(fields)
        return self

    def settings(self, **fields):
        """The ``[render]`` table: ``spp``, ``adaptive``, ``ambient``, ``background`` (linear
        ``[r, g, b]``, or ``"transparent"``: an RGBA picture), ``max_depth``, …"""
        self._render.update(fields)
        return self

    def environment(self, **fields):
        """The ``[environment]`` table: a sky gradient or an image."""
        self._environment = dict(fields)
        return self

    def light(self, **fields):
        """A ``[[lights]]`` entry: ``position`` or ``direction``, ``colour``, ``sphere``, …"""
        self._lights.append(dict(fields))
        return self

    def material(self, name, **fields):
        """A named material (``[materials.NAME]``), for objects' ``material = NAME``."""
        self._materials[name] = dict(fields)
        return self

    def add(self, kind, **fields):
        """An object of any kind of the format (``type = kind``) with its fields."""
        return self._add(kind, f"scene.add({kind!r}, …)", fields)

    def _add(self, kind, who, fields):
        if kind not in KINDS:
            raise _cga.ValueError(f"no object kind {kind!r}: the kinds are {', '.join(KINDS)}")
        self._objects.append((who, {"type": kind, **fields}))
        return self

    def draw(self, value, **fields):
        """A cga value (or each row of an array) drawn as what it is: a ``blade`` object with
        the value's coefficients, and ``fields`` (``material``, ``size``, ``tube``, …)."""
        rows = [value] if value.single else [value[i] for i in range(len(value))]
        for row in rows:
            blade = {b: float(c) for b, c in zip(type(row).blades, row.array) if c != 0.0 and b != "s"}
            self._objects.append((f"scene.draw({type(value).__name__} …)", {"type": "blade", **fields, "blade": blade}))
        return self

    def toml(self):
        """The scene as the format's text (what it is read from)."""
        return "".join(self._sections()[0])

    def _sections(self):
        """The text's sections and, for each, what call wrote it."""
        parts, whose = [], []

        def put(text, who):
            parts.append(text + "\n")
            whose.append(who)

        put(_table("[camera]", self._camera), "scene.camera(…)")
        if self._render:
            put(_table("[render]", self._render), "scene.settings(…)")
        if self._environment is not None:
            put(_table("[environment]", self._environment), "scene.environment(…)")
        for name, fields in self._materials.items():
            put(_table(f"[materials.{_key(name)}]", fields), f"scene.material({name!r}, …)")
        for k, fields in enumerate(self._lights):
            put(_table("[[lights]]", fields), f"light {k + 1} (scene.light(…))")
        for k, (who, fields) in enumerate(self._objects):
            put(_table("[[objects]]", fields), f"object {k + 1} ({who})")
        return parts, whose

    def build(self):
        """The scene checked and built, ready to render (a ``cga._cga.Scene``); an error names
        the call that wrote the field, with the line and column in :meth:`toml`'s text."""
        parts, whose = self._sections()
        text = "".join(parts)
        try:
            return _cga.Scene.parse(text, "scene built in Python")
        except _cga.SceneError as e:
            found = re.search(r":(\d+):(\d+):", str(e))
            if not found:
                raise
            line, start = int(found.group(1)), 1
            for part, who in zip(parts, whose):
                end = start + part.count("\n")
                if start <= line < end:
                    raise _cga.SceneError(f"{e} [{who}]") from None
                start = end
            raise

    def render(self, **options):
        """The picture (a ``cga.Picture``: ``.linear``, ``.srgb``, ``.save(path)``), with the
        options of ``cga._cga.Scene.render`` (``width``, ``spp``, ``exposure``,
        ``background="transparent"``, …); over a transparent background ``.linear`` and
        ``.srgb`` have a fourth channel, alpha (premultiplied linear, as EXR stores it;
        straight 8-bit, as PNG stores it), and ``.coverage`` is the alpha as floats."""
        return self.build().render(**options)


def _kind_method(kind):
    name = kind.replace("-", "_")

    def method(self, **fields):
        return self._add(kind, f"scene.{name}(…)", fields)

    method.__name__ = name
    own = ", ".join(f"``{f}``" for f in FIELDS[kind])
    method.__doc__ = f"A ``{kind}`` object: {own}, and any object's fields (docs/SCENES.md)."
    return method


for _kind in KINDS:
    setattr(Scene, _kind.replace("-", "_"), _kind_method(_kind))
