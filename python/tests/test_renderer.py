"""The high-level Renderer: depth, ids and the pinhole camera against their analytic values; bad input."""
import threading

import numpy as np
import pytest

import softgl

W, H = 160, 120
FX, FY, CX, CY = 150.0, 140.0, 79.3, 61.7


def pinhole(renderer, extrinsics=None):
    renderer.set_intrinsics(FX, FY, CX, CY, near=0.5, far=50.0, world_to_camera=extrinsics)


def project(points):
    """OpenCV's projection of camera-frame points (x right, y down, z forward) to pixel coordinates."""
    p = np.asarray(points, dtype=np.float64)
    return np.stack([FX * p[:, 0] / p[:, 2] + CX, FY * p[:, 1] / p[:, 2] + CY], axis=1)


def test_projection_matrices_reproduce_opencv():
    r = softgl.Renderer(W, H, msaa=1)
    angle = 0.3
    rot = np.array([[np.cos(angle), 0, np.sin(angle)], [0, 1, 0], [-np.sin(angle), 0, np.cos(angle)]])
    extrinsics = softgl.pose(rot, (0.2, -0.1, 4.0))
    pinhole(r, extrinsics)
    rng = np.random.default_rng(1)
    world = rng.uniform(-1.0, 1.0, size=(50, 3))
    camera = world @ rot.T + extrinsics[:3, 3]
    expected = project(camera)
    clip = (r.projection_matrix.astype(np.float64) @ r.view_matrix.astype(np.float64)
            @ np.c_[world, np.ones(len(world))].T).T
    ndc = clip[:, :3] / clip[:, 3:]
    # Window coordinates (OpenGL: y up, pixel centres at + 0.5) to OpenCV's pixel coordinates.
    u = (ndc[:, 0] + 1) / 2 * W - 0.5
    v = H - (ndc[:, 1] + 1) / 2 * H - 0.5
    assert np.abs(np.c_[u, v] - expected).max() < 0.01


def edge_distance(px, tri):
    """Signed distances of points px (N, 2) to the three edges of triangle tri (3, 2); all > 0 inside."""
    d = []
    area = np.cross(tri[1] - tri[0], tri[2] - tri[0])
    for i in range(3):
        a, b = tri[i], tri[(i + 1) % 3]
        e = b - a
        d.append(np.sign(area) * np.cross(e, px - a) / np.linalg.norm(e))
    return np.stack(d, axis=1)


def test_rendered_coverage_matches_opencv_projection():
    """Every pixel centre farther than 0.01 px from the projected triangle's edges is covered exactly when it lies
    inside: the image is OpenCV's projection to within 0.01 px."""
    r = softgl.Renderer(W, H, msaa=1, shader="unlit")
    pinhole(r)
    camera = np.array([[-1.3, -0.9, 3.0], [1.1, -0.4, 2.2], [0.1, 1.2, 4.1]], dtype=np.float32)
    r.add_mesh(camera, object_id=5)
    ids = r.render(color=False, ids=True)["ids"]
    tri = project(camera)
    v, u = np.mgrid[0:H, 0:W]
    centres = np.c_[u.ravel(), v.ravel()].astype(np.float64)
    d = edge_distance(centres, tri)
    inside = (d > 0).all(axis=1)
    clear = np.abs(d).min(axis=1) > 0.01
    covered = ids.ravel() == 5
    assert inside.sum() > 2000
    assert np.array_equal(covered[clear], inside[clear])


def test_depth_of_a_plane_is_its_analytic_depth():
    r = softgl.Renderer(W, H, msaa=4)
    pinhole(r)
    # The plane n . X = c, tilted, seen from the camera at the origin (identity extrinsics).
    n = np.array([0.2, -0.3, 1.0])
    n /= np.linalg.norm(n)
    c = 3.0
    corners = []
    for x, y in [(-3, -3), (3, -3), (3, 3), (-3, 3)]:
        z = (c - n[0] * x - n[1] * y) / n[2]
        corners.append([x, y, z])
    r.add_mesh(np.array(corners, np.float32), faces=np.array([[0, 1, 2], [0, 2, 3]]))
    depth = r.render(color=False, depth=True)["depth"]
    v, u = np.mgrid[0:H, 0:W]
    rays = np.stack([(u - CX) / FX, (v - CY) / FY, np.ones_like(u, dtype=np.float64)], axis=-1)
    expected = c / (rays @ n)
    assert (depth > 0).all()  # the plane fills the view
    assert np.abs(depth / expected - 1).max() < 1e-5


def test_ids_mask_what_each_object_covers():
    r = softgl.Renderer(W, H, msaa=4, shader="unlit")
    pinhole(r)
    # Squares at depth 5 whose edges fall on pixel boundaries (u = 9.5 ... 19.5): no edge passes a pixel centre.
    def square(u0, u1, v0, v1, z=5.0):
        corners = [(u0, v0), (u1, v0), (u1, v1), (u0, v1)]
        return np.array([[(u - CX) * z / FX, (v - CY) * z / FY, z] for u, v in corners], np.float32)
    faces = np.array([[0, 1, 2], [0, 2, 3]])
    ids = {7: (9.5, 19.5, 4.5, 30.5), 300: (39.5, 80.5, 59.5, 61.5), 3_000_000_000: (99.5, 159.5, 0 - 0.5, 119.5)}
    for object_id, (u0, u1, v0, v1) in ids.items():
        r.add_mesh(square(u0, u1, v0, v1), faces, object_id=object_id)
    # A nearer object hides part of the last one.
    r.add_mesh(square(119.5, 129.5, 9.5, 19.5, z=2.0), faces, object_id=9)
    out = r.render(ids=True, depth=True)
    mask = out["ids"]
    expected = np.zeros((H, W), np.uint32)
    for object_id, (u0, u1, v0, v1) in ids.items():
        expected[int(v0 + 0.5):int(v1 + 0.5), int(u0 + 0.5):int(u1 + 0.5)] = object_id
    expected[10:20, 120:130] = 9
    assert np.array_equal(mask, expected)
    assert np.array_equal(out["depth"] > 0, expected > 0)
    assert np.allclose(out["depth"][expected == 9], 2.0, rtol=1e-6)


def test_normals_face_the_camera():
    r = softgl.Renderer(64, 64, msaa=1)
    r.look_at((0, 0, 4), (0, 0, 0))
    quad = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], np.float32)
    r.add_mesh(quad, faces=np.array([[0, 2, 1], [0, 3, 2]]))  # wound clockwise: its face points away
    out = r.render(color=False, normals=True, ids=True)
    normals = out["normals"][out["ids"] > 0]
    assert len(normals) > 100 and np.allclose(normals, [0, 0, 1])
    assert (out["normals"][out["ids"] == 0] == 0).all()


def test_model_file_and_arrays_agree(tmp_path):
    obj = tmp_path / "cube.obj"
    v = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
    f = [(1, 3, 2), (1, 4, 3), (5, 6, 7), (5, 7, 8), (1, 2, 6), (1, 6, 5), (4, 8, 7), (4, 7, 3), (1, 5, 8),
         (1, 8, 4), (2, 3, 7), (2, 7, 6)]
    obj.write_text("".join(f"v {x} {y} {z}\n" for x, y, z in v) + "".join(f"f {a} {b} {c}\n" for a, b, c in f))
    pose = softgl.pose(translation=(0.3, 0.0, 0.0))
    outputs = []
    for from_file in (True, False):
        r = softgl.Renderer(96, 72, msaa=1)
        r.look_at((3, 2.5, 4), (0, 0, 0))
        if from_file:
            r.add_model(str(obj), pose=pose, object_id=4)
        else:
            r.add_mesh(np.array(v, np.float32), faces=np.array(f) - 1, pose=pose, object_id=4)
        outputs.append(r.render(color=False, depth=True, ids=True))
    assert (outputs[0]["ids"] == 4).sum() > 500
    assert np.array_equal(outputs[0]["ids"], outputs[1]["ids"])
    assert np.array_equal(outputs[0]["depth"], outputs[1]["depth"])


def test_colour_image_and_texture_orientation():
    r = softgl.Renderer(32, 32, msaa=1, shader="unlit")
    r.look_at((0, 0, 2), (0, 0, 0), fov_y=60)
    quad = np.array([[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]], np.float32)
    uvs = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], np.float32)
    texture = np.zeros((2, 2, 3), np.uint8)
    texture[0] = (255, 0, 0)  # top row red
    texture[1] = (0, 0, 255)  # bottom row blue
    r.add_mesh(quad, faces=np.array([[0, 1, 2], [0, 2, 3]]), uvs=uvs, texture=texture)
    color = r.render()["color"]
    assert color.shape == (32, 32, 3)
    # The 2 x 2 texture is magnified with LINEAR filtering (and REPEAT): red fades into blue down the image.
    column = color[:, 16].astype(int)
    assert column[4, 0] > 240 and column[4, 2] < 90  # top of the image: the texture's top row, red
    assert column[27, 2] > 240 and column[27, 0] < 90  # bottom: blue
    assert (np.diff(column[3:29, 0]) < 0).all()


def test_renderers_in_threads_give_the_same_images():
    def scene():
        r = softgl.Renderer(128, 96, msaa=4, threads=1)
        r.look_at((2, 1.5, 3), (0, 0, 0))
        rng = np.random.default_rng(3)
        r.add_mesh(rng.uniform(-1, 1, size=(300, 3)).astype(np.float32),
                   colors=rng.uniform(0, 1, size=(300, 3)).astype(np.float32))
        return r
    alone = scene().render(depth=True)
    results = [None] * 4

    def work(i):
        results[i] = scene().render(depth=True)
    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for out in results:
        assert np.array_equal(out["color"], alone["color"]) and np.array_equal(out["depth"], alone["depth"])


QUAD = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0]], np.float32)


@pytest.mark.parametrize("kwargs, error, message", [
    (dict(positions=QUAD.astype(np.int32)), TypeError, "positions: dtype must be float32 or float64"),
    (dict(positions=QUAD[:, :2].copy()), ValueError, r"positions: shape must be \(N, 3\)"),
    (dict(positions=np.asfortranarray(np.tile(QUAD, (2, 1)))), ValueError, "positions: the array must be C-contiguous"),
    (dict(positions=np.zeros((0, 3), np.float32)), ValueError, "positions: the mesh is empty"),
    (dict(positions=QUAD[:2].copy()), ValueError, "multiple of 3"),
    (dict(positions=np.where(np.eye(3, dtype=bool), np.nan, QUAD).astype(np.float32)), ValueError,
     "positions: row 0 holds NaN"),
    (dict(positions=[[0, 0, 0]]), TypeError, "positions: expected a numpy array"),
    (dict(positions=QUAD, faces=np.array([[0, 1, 3]])), ValueError, "faces: index 3 in row 0 is outside the 3 vertices"),
    (dict(positions=QUAD, faces=np.array([[0, -1, 2]])), ValueError, "faces: index -1"),
    (dict(positions=QUAD, faces=np.zeros((0, 3), np.int32)), ValueError, "faces: the mesh has no triangles"),
    (dict(positions=QUAD, faces=np.array([[0.0, 1.0, 2.0]])), TypeError, "faces: dtype must be an integer type"),
    (dict(positions=QUAD, normals=np.zeros((2, 3), np.float32)), ValueError, "normals: one row per vertex"),
    (dict(positions=QUAD, colors=np.zeros((3, 5), np.float32)), ValueError, "colors: shape"),
    (dict(positions=QUAD, texture=np.zeros((2, 2, 3), np.uint8)), ValueError, "texture: needs uvs"),
    (dict(positions=QUAD, uvs=np.zeros((3, 2), np.float32), texture=np.zeros((2, 2, 3), np.float32)), TypeError,
     "texture: dtype must be uint8"),
    (dict(positions=QUAD, pose=np.eye(3)), ValueError, r"pose: shape must be \(4, 4\)"),
    (dict(positions=QUAD, object_id=-2), ValueError, "object_id"),
])
def test_bad_meshes_are_refused(kwargs, error, message):
    r = softgl.Renderer(8, 8)
    with pytest.raises(error, match=message):
        r.add_mesh(**kwargs)
    assert r.object_count == 0


def test_bad_cameras_files_and_settings_are_refused(tmp_path):
    r = softgl.Renderer(8, 8)
    with pytest.raises(ValueError, match="fx, fy"):
        r.set_intrinsics(0.0, 100.0, 4, 4)
    with pytest.raises(ValueError, match="far: must be finite and greater than near"):
        r.set_intrinsics(100.0, 100.0, 4, 4, near=2.0, far=2.0)
    with pytest.raises(ValueError, match="near: must be a finite number > 0"):
        r.look_at((0, 0, 1), (0, 0, 0), near=0.0)
    with pytest.raises(ValueError, match="target: must differ from eye"):
        r.look_at((0, 0, 1), (0, 0, 1))
    with pytest.raises(ValueError, match="world_to_camera: holds NaN"):
        r.set_intrinsics(100.0, 100.0, 4, 4, world_to_camera=np.full((4, 4), np.nan))
    with pytest.raises(FileNotFoundError, match="path: no such file"):
        r.add_model(str(tmp_path / "missing.glb"))
    corrupt = tmp_path / "corrupt.ply"
    corrupt.write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 99999999\nend_header\n\x00")
    with pytest.raises(ValueError, match="path: "):
        r.add_model(str(corrupt))
    with pytest.raises(ValueError, match="msaa"):
        softgl.Renderer(8, 8, msaa=3)
    with pytest.raises(ValueError, match="shader"):
        softgl.Renderer(8, 8, shader="toon")
    with pytest.raises(ValueError, match="width"):
        softgl.Renderer(0, 8)
    with pytest.raises(ValueError, match="tone_map"):
        r.set_tone_map("filmic")
    with pytest.raises(IndexError, match="handle"):
        r.set_pose(42, np.eye(4))
    # Nothing to draw is not an error: an empty image.
    out = r.render(depth=True, ids=True)
    assert (out["ids"] == 0).all() and (out["depth"] == 0).all()


def test_look_at_extrinsics():
    eye, target = np.array([0.5, 0.2, 3.0]), np.array([0.5, 0.2, 0.0])
    m = softgl.look_at(eye, target)
    def pixel(p):
        c = m[:3, :3] @ p + m[:3, 3]
        return project(c[None])[0]
    assert np.allclose(pixel(target), [CX, CY])
    above, right = pixel(target + [0, 1, 0]), pixel(target + [1, 0, 0])
    assert above[1] < CY and np.isclose(above[0], CX)  # image rows grow downwards
    assert right[0] > CX and np.isclose(right[1], CY)
    assert np.allclose(m[:3, :3] @ m[:3, :3].T, np.eye(3))
    with pytest.raises(ValueError, match="up"):
        softgl.look_at(eye, target, up=(0, 0, 1))


@pytest.mark.parametrize("shader", ["unlit", "phong", "pbr"])
def test_hdr_colour_is_the_uint8_colour_before_its_clamp_and_encoding(shader):
    r = softgl.Renderer(64, 48, msaa=1, shader=shader)
    r.look_at((0, 0, 3), (0, 0, 0))
    colors = np.random.default_rng(0).uniform(0, 1, (3, 3)).astype(np.float32)
    r.add_mesh(np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], np.float32), colors=colors, roughness=0.3)
    r.set_lights([((0, 0.3, 1), (3.0, 2.5, 2.0))])  # bright enough to go past 1
    r.set_tone_map("clamp")
    low = r.render()["color"].astype(np.float64)
    high = r.render(hdr=True)["color"]
    assert high.dtype == np.float32 and high.shape == (48, 64, 3)
    if shader != "unlit":
        assert high.max() > 1.5
    c = np.clip(high.astype(np.float64), 0, 1)
    if shader == "pbr":  # linear light, sRGB-encoded in the uint8 image
        c = np.where(c <= 0.0031308, c * 12.92, 1.055 * c ** (1 / 2.4) - 0.055)
    assert np.abs(np.round(c * 255) - low).max() <= 1


def test_blended_materials_write_depth_normals_and_ids(tmp_path):
    (tmp_path / "glass.mtl").write_text("newmtl glass\nKd 0.2 0.6 0.9\nd 0.4\n")
    (tmp_path / "glass.obj").write_text("mtllib glass.mtl\nusemtl glass\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                        "vn 0 0 1\nf 1//1 2//1 3//1\nf 1//1 3//1 4//1\n")
    r = softgl.Renderer(32, 32, msaa=1)
    r.look_at((0, 0, 2), (0, 0, 0), fov_y=40)
    r.add_model(str(tmp_path / "glass.obj"), object_id=3)
    out = r.render(depth=True, normals=True, ids=True, alpha=True)
    drawn = out["ids"] == 3
    assert drawn.sum() > 300
    assert np.allclose(out["depth"][drawn], 2.0, rtol=1e-5)
    assert np.allclose(out["normals"][drawn], [0, 0, 1])
    assert abs(int(out["color"][16, 16, 3]) - 41) <= 1  # blended: alpha 0.4 x 0.4 over a clear alpha of 0


def box_triangles(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    v = np.array([[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0], [x0, y0, z1], [x1, y0, z1], [x1, y1, z1],
                  [x0, y1, z1]], np.float32)
    f = [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4], [3, 7, 6], [3, 6, 2], [0, 4, 7], [0, 7, 3],
         [1, 2, 6], [1, 6, 5]]
    return v[np.ravel(f)]  # a triangle list: each face its own vertices, so its own normal


@pytest.mark.parametrize("shader", ["phong", "pbr"])
def test_shadows_darken_the_floor_under_a_box_and_nothing_else(shader):
    light = np.array([-0.5, 1.0, -0.4])  # the shadow falls towards the camera
    images = []
    for shadows in (False, True):
        r = softgl.Renderer(160, 120, msaa=1, shader=shader)  # (with samples, an edge pixel mixes box and floor)
        floor = np.array([[-3, 0, -3], [3, 0, -3], [3, 0, 3], [-3, 0, 3]], np.float32)
        r.add_mesh(floor, faces=np.array([[0, 2, 1], [0, 3, 2]]), color=(0.6, 0.6, 0.6, 1), object_id=1)
        r.add_mesh(box_triangles((-0.6, 0.5, -0.6), (0.6, 1.7, 0.6)), color=(0.9, 0.4, 0.2, 1), object_id=2)
        r.look_at((3.5, 3, 5), (0, 0.5, 0), fov_y=40)
        r.set_lights([(light, (1, 1, 1)), ((-0.5, 0.6, 0.8), (0.3, 0.3, 0.35))], ambient=(0.1, 0.1, 0.1))
        r.set_shadows(shadows)
        images.append(r.render(ids=True))
    off, on = (out["color"].astype(int) for out in images)
    ids = images[0]["ids"]
    changed = (off != on).any(axis=-1)
    assert 100 < changed.sum() < 0.2 * changed.size
    assert (ids[changed] == 1).all()  # only the floor: the box's lit faces are the same bytes
    assert (on <= off).all()  # darker, never brighter
    # The box's centre seen from the light falls on the floor here, deep in the shadow.
    centre = np.array([0.0, 1.1, 0.0])
    ground = centre - light / np.linalg.norm(light) * (1.1 / (light[1] / np.linalg.norm(light)))
    clip = (r.projection_matrix.astype(np.float64) @ r.view_matrix.astype(np.float64) @ np.r_[ground, 1.0])
    u = int((clip[0] / clip[3] + 1) / 2 * 160)
    v = int(120 - (clip[1] / clip[3] + 1) / 2 * 120)
    assert changed[v, u] and off[v, u].sum() - on[v, u].sum() > 150


def test_points_and_lines_land_where_the_camera_projects_them():
    r = softgl.Renderer(W, H, msaa=1)
    pinhole(r)
    # Points whose projections are pixel centres: one pixel each (size 1), at their depth.
    pixels = np.array([[10, 12], [80, 60], [150, 100], [33, 97]], np.float64)
    z = np.array([2.0, 3.0, 4.5, 6.0])
    points = np.c_[(pixels[:, 0] - CX) * z / FX, (pixels[:, 1] - CY) * z / FY, z].astype(np.float32)
    r.add_points(points, colors=np.array([[255, 0, 0]] * 4, np.uint8), object_id=11)
    # A segment along the pixel centres of row 30, columns 20 to 60, at depth 5.
    ends = np.array([[20, 30], [60, 30]], np.float64)
    segment = np.c_[(ends[:, 0] - CX) * 5 / FX, (ends[:, 1] - CY) * 5 / FY, [5, 5]].astype(np.float32)
    r.add_lines(segment, object_id=12, width=1)
    out = r.render(depth=True, ids=True, normals=True)
    ids = out["ids"]
    assert set(zip(*np.nonzero(ids == 11))) == {(int(v), int(u)) for u, v in pixels}
    assert np.allclose(out["depth"][pixels[:, 1].astype(int), pixels[:, 0].astype(int)], z, rtol=1e-6)
    assert (out["color"][ids == 11] == [255, 0, 0]).all()  # unlit: the colour as given
    rows, cols = np.nonzero(ids == 12)
    assert set(rows) == {30} and 39 <= len(cols) <= 41 and cols.min() >= 20 and cols.max() <= 60
    assert (out["normals"][ids > 0] == 0).all()
    with pytest.raises(ValueError, match="must be even"):
        r.add_lines(points[:3])
    with pytest.raises(ValueError, match="segments: index 9"):
        r.add_lines(points, segments=np.array([[0, 9]]))
    with pytest.raises(ValueError, match="size: must be 1 to"):
        r.add_points(points, size=0.0)
