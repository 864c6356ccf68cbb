"""The low-level API: OpenGL's calls from Python, the same bytes as the C++ API, errors as exceptions."""
import subprocess

import numpy as np
import pytest

import softgl as gl


def draw_reference_scene():
    """python/tests/reference.cpp's scene, call for call."""
    ctx = gl.Context(96, 64)
    vertices = np.array([
        [-0.9, -0.8, -0.5, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
        [0.8, -0.9, -0.7, 0.0, 0.6, 0.8, 2.0, 0.0, 1.0, 0.5, 0.5, 1.0],
        [0.9, 0.9, -0.9, 0.6, 0.0, 0.8, 2.0, 2.0, 0.5, 1.0, 0.5, 1.0],
        [-0.8, 0.8, -0.6, 0.0, 0.0, 1.0, 0.0, 2.0, 0.5, 0.5, 1.0, 1.0],
        [-0.5, -0.6, -0.2, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.2, 0.1, 0.5],
        [0.7, -0.2, -0.3, 0.0, 0.0, 1.0, 0.0, 0.0, 0.1, 1.0, 0.2, 0.5],
        [-0.1, 0.7, -1.2, 0.0, 0.0, 1.0, 0.0, 0.0, 0.2, 0.1, 1.0, 0.5],
    ], dtype=np.float32)
    indices = np.array([0, 1, 2, 0, 2, 3, 4, 5, 6], dtype=np.uint16)
    vao = ctx.gen_vertex_array()
    ctx.bind_vertex_array(vao)
    vbo, ebo = ctx.gen_buffer(), ctx.gen_buffer()
    ctx.bind_buffer(gl.ARRAY_BUFFER, vbo)
    ctx.buffer_data(gl.ARRAY_BUFFER, vertices)
    ctx.bind_buffer(gl.ELEMENT_ARRAY_BUFFER, ebo)
    ctx.buffer_data(gl.ELEMENT_ARRAY_BUFFER, indices)
    ctx.vertex_attribute_pointer(gl.ATTRIB_POSITION, 3, gl.FLOAT, False, 48, 0)
    ctx.vertex_attribute_pointer(gl.ATTRIB_NORMAL, 3, gl.FLOAT, False, 48, 12)
    ctx.vertex_attribute_pointer(gl.ATTRIB_UV, 2, gl.FLOAT, False, 48, 24)
    ctx.vertex_attribute_pointer(gl.ATTRIB_COLOR, 4, gl.FLOAT, False, 48, 32)
    for i in (0, 1, 2, 4):
        ctx.enable_vertex_attrib_array(i)
    ctx.vertex_attrib4f(gl.ATTRIB_TANGENT, 0.0, 0.0, 0.0, 1.0)

    y, x = np.mgrid[0:4, 0:8]
    texels = np.stack([32 * x, 60 * y, 255 - 30 * x, np.full_like(x, 255)], axis=-1).astype(np.uint8)
    texture = ctx.gen_texture()
    ctx.active_texture(gl.TEXTURE0)
    ctx.bind_texture(gl.TEXTURE_2D, texture)
    ctx.tex_image_2d(gl.TEXTURE_2D, 0, gl.SRGB8_ALPHA8, texels)  # first row the bottom, as the C++ program's
    ctx.generate_mipmap(gl.TEXTURE_2D)
    ctx.tex_parameter(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR)
    ctx.tex_parameter(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR)

    view_proj = np.array([[1.25, 0, 0, 0], [0, 1.5, 0, 0], [0, 0, -1.25, -0.5], [0, 0, -1, 0.5]])
    shader = gl.PhongShader()
    shader.set_transforms(np.eye(4), view_proj)
    shader.base_color = (1.0, 0.9, 0.8, 1.0)
    shader.base_color_texture = texture
    shader.shininess = 16.0
    shader.set_lights([((0, 0, 1), (0.9, 0.85, 0.8)), ((0.6, 0, 0.8), (0.25, 0.3, 0.5))],
                      ambient=(0.1, 0.1, 0.12), eye=(0, 0, 2))
    ctx.use_program(shader)
    ctx.clear_color(0.1, 0.2, 0.3, 1.0)
    ctx.enable(gl.DEPTH_TEST)
    ctx.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT)
    ctx.draw_element(gl.TRIANGLES, 6, gl.UNSIGNED_SHORT, 0)
    unlit = gl.UnlitShader()
    unlit.set_transforms(np.eye(4), view_proj)
    unlit.base_color = (1.0, 1.0, 1.0, 0.75)
    unlit.alpha_mode = "blend"
    ctx.use_program(unlit)
    ctx.enable(gl.BLEND)
    ctx.blend_func(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA)
    ctx.draw_element(gl.TRIANGLES, 3, gl.UNSIGNED_SHORT, 12)
    return ctx


def test_same_bytes_as_the_cpp_api(reference_program, tmp_path):
    out = tmp_path / "reference.rgba"
    subprocess.run([reference_program, str(out)], check=True)
    expected = np.frombuffer(out.read_bytes(), dtype=np.uint8).reshape(64, 96, 4)
    got = draw_reference_scene().read_pixels(flip=False)
    assert got.shape == (64, 96, 4) and got.dtype == np.uint8
    # The scene covers most of the target with several colours: a comparison of something drawn.
    assert len(np.unique(got.reshape(-1, 4), axis=0)) > 100
    assert np.array_equal(got, expected)


def test_read_pixels_rows_and_types():
    ctx = gl.Context(8, 6)
    ctx.clear_color(0.0, 0.0, 0.0, 1.0)
    ctx.clear(gl.COLOR_BUFFER_BIT)
    ctx.enable(gl.SCISSOR_TEST)
    ctx.scissor(0, 0, 8, 2)  # the bottom two rows
    ctx.clear_color(1.0, 0.5, 0.0, 1.0)
    ctx.clear(gl.COLOR_BUFFER_BIT)
    image = ctx.read_pixels()  # top row first
    assert image.shape == (6, 8, 4)
    assert (image[4:, :, 0] == 255).all() and (image[:4, :, 0] == 0).all()
    bottom_first = ctx.read_pixels(flip=False)
    assert np.array_equal(bottom_first, image[::-1])
    floats = ctx.read_pixels(format=gl.RGB, type=gl.FLOAT)
    assert floats.dtype == np.float32 and floats.shape == (6, 8, 3)
    assert floats[5, 0, 1] == pytest.approx(128 / 255)
    depth = ctx.read_pixels(format=gl.DEPTH_COMPONENT, type=gl.FLOAT)
    assert depth.shape == (6, 8) and (depth == 1.0).all()
    # A rectangle inside: x, y from the bottom left as in OpenGL, rows packed tight (3 RGB bytes a pixel, no padding).
    part = ctx.read_pixels(2, 1, 5, 3, format=gl.RGB)
    assert part.shape == (3, 5, 3)
    assert np.array_equal(part, image[6 - (1 + 3):6 - 1, 2:7, :3])  # rows y = 1 .. 3 from the bottom


def test_gl_errors_raise_with_their_names():
    ctx = gl.Context(4, 4)
    with pytest.raises(gl.GLError, match="INVALID_ENUM in bind_buffer"):
        ctx.bind_buffer(0x1234, 0)
    with pytest.raises(gl.GLError, match="INVALID_OPERATION in bind_vertex_array"):
        ctx.bind_vertex_array(999)
    with pytest.raises(gl.GLError, match="INVALID_VALUE"):
        ctx.viewport(0, 0, -1, 4)
    with pytest.raises(gl.GLError, match="INVALID_OPERATION in draw_arrays"):
        ctx.draw_arrays(gl.TRIANGLES, 0, 3)  # no program in use
    assert ctx.get_error() == gl.NO_ERROR  # each error was raised once, and taken


def test_bad_arrays_are_refused():
    ctx = gl.Context(4, 4)
    ctx.bind_buffer(gl.ARRAY_BUFFER, ctx.gen_buffer())
    strided = np.zeros((4, 6), np.float32)[:, ::2]
    with pytest.raises(ValueError, match="data: the data must be C-contiguous"):
        ctx.buffer_data(gl.ARRAY_BUFFER, strided)
    ctx.bind_texture(gl.TEXTURE_2D, ctx.gen_texture())
    with pytest.raises(TypeError, match="image: dtype"):
        ctx.tex_image_2d(gl.TEXTURE_2D, 0, gl.RGBA8, np.zeros((2, 2, 4), np.int64))
    with pytest.raises(ValueError, match=r"image: shape"):
        ctx.tex_image_2d(gl.TEXTURE_2D, 0, gl.RGBA8, np.zeros((2, 2, 5), np.uint8))
    with pytest.raises(TypeError, match="image: expected a numpy array"):
        ctx.tex_image_2d(gl.TEXTURE_2D, 0, gl.RGBA8, [[1, 2], [3, 4]])
    with pytest.raises(ValueError, match="width, height"):
        gl.Context(-1, 4)


def test_model_files(tmp_path):
    obj = tmp_path / "quad.obj"
    obj.write_text("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n")
    ctx = gl.Context(16, 16)
    model = gl.Model.load(ctx, str(obj))
    assert model.triangles == 2 and model.mesh_count == 1
    assert model.bounds == ([-1.0, -1.0, 0.0], [1.0, 1.0, 0.0])
    shader = gl.UnlitShader()
    shader.base_color = (0.0, 1.0, 0.0, 1.0)  # replaced by the file's material: assimp's default grey, 0.6
    ctx.clear(gl.COLOR_BUFFER_BIT)
    model.draw(ctx, shader, np.diag([0.5, 0.5, 0.5, 1.0]))
    image = ctx.read_pixels()
    assert (image[4:12, 4:12, :3] == 153).all()
    assert (image[:4, :, :3] == 0).all() and (image[12:, :, :3] == 0).all()
    with pytest.raises(FileNotFoundError, match="path: no such file"):
        gl.Model.load(ctx, str(tmp_path / "missing.obj"))
    bad = tmp_path / "bad.glb"
    bad.write_bytes(b"glTF\x02\x00\x00\x00garbage")
    with pytest.raises(ValueError, match="path: "):
        gl.Model.load(ctx, str(bad))
