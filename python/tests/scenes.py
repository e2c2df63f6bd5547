"""Small meshes and scenes the facet module's tests draw (vertices, faces as NumPy arrays)."""
import numpy as np

import facet


def quad(z=0.0, half=1.0):
    """A square in the plane z, facing +Z (counter-clockwise seen from +Z), with uvs."""
    vertices = np.array(
        [[-half, -half, z], [half, -half, z], [half, half, z], [-half, half, z]], np.float32
    )
    faces = np.array([[0, 1, 2], [0, 2, 3]], np.int64)
    uvs = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], np.float32)
    return vertices, faces, uvs


def triangle():
    vertices = np.array([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], np.float32)
    faces = np.array([[0, 1, 2]], np.int32)
    return vertices, faces


def unlit(color=(1.0, 1.0, 1.0)):
    return facet.Material(base_color=color, shading="unlit")


def front_camera(distance=3.0, fov_y=60.0):
    """Looks down -Z at the origin from distance along +Z."""
    return facet.Camera.look_at((0, 0, distance), (0, 0, 0), (0, 1, 0), fov_y, 0.1, 100.0)


def icosphere(subdivisions=1):
    """A unit sphere of triangles, counter-clockwise seen from outside."""
    t = (1.0 + 5.0**0.5) / 2.0
    vertices = [
        (-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
        (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1),
    ]
    faces = [
        (0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
        (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
        (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1),
    ]
    vertices = [np.array(v, np.float64) / np.linalg.norm(v) for v in vertices]
    for _ in range(subdivisions):
        middle = {}

        def between(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                m = vertices[a] + vertices[b]
                vertices.append(m / np.linalg.norm(m))
                middle[key] = len(vertices) - 1
            return middle[key]

        finer = []
        for a, b, c in faces:
            ab, bc, ca = between(a, b), between(b, c), between(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = finer
    return np.array(vertices, np.float32), np.array(faces, np.int64)


def write_obj(path, vertices, faces, name="sphere"):
    """A Wavefront OBJ of one object (1-based indices)."""
    lines = [f"o {name}"]
    lines += [f"v {x} {y} {z}" for x, y, z in vertices]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces]
    path.write_text("\n".join(lines) + "\n")
    return path


def ball_on_a_floor():
    """A phong ball on a vertex-colored floor, lit by a point light: a scene factory for
    facet.dask ("scenes:ball_on_a_floor"), made on each worker."""
    scene = facet.Scene()
    vertices, faces = icosphere(2)
    scene.add_mesh(vertices, faces, normals=vertices,
                   material=facet.Material((0.2, 0.5, 0.9), "phong"))
    floor = np.array([[-3, -1, -3], [3, -1, -3], [3, -1, 3], [-3, -1, 3]], np.float32)
    scene.add_mesh(floor, [[0, 2, 1], [0, 3, 2]], colors=np.full((4, 3), 170, np.uint8))
    scene.add_light(facet.Light.point((2, 3, 2), intensity=5))
    return scene
