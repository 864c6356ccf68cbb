"""softgl: a software rasterizer with OpenGL's model, for Python.

No GPU, no display, no OpenGL driver: the pixels are computed by softgl's C++ pipeline and come back as numpy
arrays, the same on every machine.

Two levels:

* ``Renderer``: meshes from numpy arrays or model files, a camera (look-at or OpenCV pinhole intrinsics), lights,
  the built-in unlit, Phong and PBR shaders; ``render()`` returns colour, depth, normals and instance ids.
* ``Context``: OpenGL's own model (buffers, vertex arrays, textures, framebuffers, draws, ``read_pixels``) with the
  built-in shaders (``UnlitShader``, ``PhongShader``, ``PbrShader``) and ``Model`` files.

Every OpenGL constant is a module attribute (``softgl.TRIANGLES``, ``softgl.RGBA8``...). A call that OpenGL would
answer with an error raises ``softgl.GLError`` naming it; bad arrays raise ``TypeError`` or ``ValueError`` naming
the argument.
"""

from ._softgl import *  # noqa: F401,F403
from ._softgl import GLError, Renderer, Context, Model  # noqa: F401
from . import _softgl

import numpy as _np

__all__ = [name for name in dir(_softgl) if not name.startswith("_")] + ["look_at", "pose"]


def look_at(eye, target, up=(0.0, 1.0, 0.0)):
    """The 4 x 4 world-to-camera matrix of a camera at ``eye`` looking at ``target`` in OpenCV's convention
    (x right, y down, z forward): the ``world_to_camera`` of ``Renderer.set_intrinsics``."""
    eye = _np.asarray(eye, dtype=_np.float64)
    forward = _np.asarray(target, dtype=_np.float64) - eye
    norm = _np.linalg.norm(forward)
    if norm == 0.0:
        raise ValueError("target: must differ from eye")
    z = forward / norm
    x = _np.cross(z, _np.asarray(up, dtype=_np.float64))
    if _np.linalg.norm(x) < 1e-12:
        raise ValueError("up: must not be parallel to the view direction")
    x /= _np.linalg.norm(x)
    y = _np.cross(z, x)
    m = _np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = x, y, z
    m[:3, 3] = -m[:3, :3] @ eye
    return m


def pose(rotation=None, translation=(0.0, 0.0, 0.0)):
    """A 4 x 4 transform from a 3 x 3 rotation matrix (identity when None) and a translation."""
    m = _np.eye(4)
    if rotation is not None:
        r = _np.asarray(rotation, dtype=_np.float64)
        if r.shape != (3, 3):
            raise ValueError(f"rotation: shape must be (3, 3), got {r.shape}")
        m[:3, :3] = r
    m[:3, 3] = _np.asarray(translation, dtype=_np.float64)
    return m
