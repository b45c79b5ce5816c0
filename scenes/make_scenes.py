#!/usr/bin/env python3
"""Generate vkpt's glTF 2.0 test scenes (standard library only).

  cornell.gltf/.bin  - the GAMES101 homework-7 Cornell box (models/cornellbox/*.obj)
  furnace.gltf/.bin  - closed emissive+diffuse sphere with an analytic answer
  many_lights.gltf/.bin - a hall lit by 1,000 small emissive quads of varied power and
                       orientation (light sampling among many lights)

Usage: python3 make_scenes.py [--out DIR]   (default: this script's directory)

Winding is load-bearing: vkpt emits light only from a triangle's front face
(glTF CCW, normal = (v1-v0) x (v2-v0)), so every quad is oriented by an explicit
rule below and asserted, rather than trusting the order the vertices are listed in.
"""
import argparse
import json
import math
import os
import struct

FLOAT, UNSIGNED_SHORT = 5126, 5123
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
TRIANGLES = 4


def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def dot(a, b): return sum(x * y for x, y in zip(a, b))
def centroid(pts): return tuple(sum(c) / len(pts) for c in zip(*pts))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def tri_normal(a, b, c):
    n = cross(sub(b, a), sub(c, a))
    length = math.sqrt(dot(n, n))
    return tuple(x / length for x in n)


def tri_area(a, b, c):
    n = cross(sub(b, a), sub(c, a))
    return 0.5 * math.sqrt(dot(n, n))


def f32(x):
    # Round-trip through float32 so accessor min/max equal the stored data exactly.
    # (+ 0.0 turns -0.0 into 0.0 so normals print cleanly.)
    return struct.unpack('<f', struct.pack('<f', x))[0] + 0.0


def orient_quads(quads, facing):
    """Split quads into triangles whose front face points along facing(point).

    A quad is reversed as a whole (a,b,c,d -> a,d,c,b) so both halves keep the
    same a-c diagonal; that matters for the slightly non-planar red wall."""
    tris = []
    for q in quads:
        a, b, c, d = q
        if dot(tri_normal(a, b, c), facing(centroid(q))) < 0:
            a, b, c, d = a, d, c, b
        for t in ((a, b, c), (a, c, d)):
            assert dot(tri_normal(*t), facing(centroid(t))) > 0, ('bad winding', t)
            tris.append(t)
    return tris


class Gltf:
    """Minimal glTF builder: one .bin buffer, one indexed primitive per mesh."""

    def __init__(self, extras=None):
        asset = {'version': '2.0', 'generator': 'vkpt scenes/make_scenes.py'}
        if extras:
            asset['extras'] = extras
        self.doc = {'asset': asset, 'scene': 0, 'scenes': [{'nodes': []}], 'nodes': [],
                    'meshes': [], 'materials': [], 'accessors': [], 'bufferViews': []}
        self.bin = bytearray()

    def _add(self, key, obj):
        self.doc.setdefault(key, []).append(obj)
        return len(self.doc[key]) - 1

    def _node(self, node):
        self.doc['scenes'][0]['nodes'].append(self._add('nodes', node))

    def _accessor(self, data, target, component, count, type_, **extra):
        self.bin += b'\0' * (-len(self.bin) % 4)  # every view starts 4-byte aligned
        view = self._add('bufferViews', {'buffer': 0, 'byteOffset': len(self.bin),
                                         'byteLength': len(data), 'target': target})
        self.bin += data
        return self._add('accessors', dict(bufferView=view, componentType=component,
                                           count=count, type=type_, **extra))

    def material(self, name, base, emissive=None, strength=None):
        # Lambertian, as the GAMES101 reference and the furnace's analytic answer assume:
        # KHR_materials_specular with specularFactor 0 removes glTF's specular layer.
        mat = {'name': name, 'doubleSided': False,
               'pbrMetallicRoughness': {'baseColorFactor': list(base) + [1.0],
                                        'metallicFactor': 0.0, 'roughnessFactor': 1.0},
               'extensions': {'KHR_materials_specular': {'specularFactor': 0.0}}}
        self.use('KHR_materials_specular')
        if emissive:
            mat['emissiveFactor'] = list(emissive)
        if strength is not None:
            mat['extensions']['KHR_materials_emissive_strength'] = {'emissiveStrength': strength}
            self.use('KHR_materials_emissive_strength')
        return self._add('materials', mat)

    def use(self, extension):
        if extension not in self.doc.setdefault('extensionsUsed', []):
            self.doc['extensionsUsed'].append(extension)

    def mesh(self, name, tris, material):
        # Flat shading: vertices are shared only where position AND face normal
        # agree, so planar quads give 4 vertices and non-planar ones 6.
        verts, index_of, indices = [], {}, []
        for t in tris:
            n = tuple(f32(x) for x in tri_normal(*t))
            for p in t:
                key = (tuple(f32(x) for x in p), n)
                if key not in index_of:
                    index_of[key] = len(verts)
                    verts.append(key)
                indices.append(index_of[key])
        assert len(verts) < 65536, 'too many vertices for UNSIGNED_SHORT indices'
        pos = [v[0] for v in verts]
        attrs = {
            'POSITION': self._accessor(
                b''.join(struct.pack('<3f', *p) for p in pos), ARRAY_BUFFER, FLOAT,
                len(verts), 'VEC3', min=[min(c) for c in zip(*pos)],
                max=[max(c) for c in zip(*pos)]),
            'NORMAL': self._accessor(
                b''.join(struct.pack('<3f', *v[1]) for v in verts), ARRAY_BUFFER,
                FLOAT, len(verts), 'VEC3'),
        }
        idx = self._accessor(struct.pack('<%dH' % len(indices), *indices),
                             ELEMENT_ARRAY_BUFFER, UNSIGNED_SHORT, len(indices), 'SCALAR')
        prim = {'attributes': attrs, 'indices': idx, 'material': material, 'mode': TRIANGLES}
        self._node({'name': name, 'mesh': self._add('meshes', {'name': name,
                                                                'primitives': [prim]})})

    def camera(self, yfov, translation=None, rotation=None):
        cam = self._add('cameras', {'type': 'perspective', 'perspective': {
            'yfov': yfov, 'aspectRatio': 1.0, 'znear': 0.1}})
        node = {'name': 'camera', 'camera': cam}
        if translation:
            node['translation'] = list(translation)
        if rotation:
            node['rotation'] = list(rotation)
        self._node(node)

    def save(self, out_dir, stem):
        self.bin += b'\0' * (-len(self.bin) % 4)
        self.doc['buffers'] = [{'uri': stem + '.bin', 'byteLength': len(self.bin)}]
        with open(os.path.join(out_dir, stem + '.bin'), 'wb') as f:
            f.write(self.bin)
        with open(os.path.join(out_dir, stem + '.gltf'), 'w') as f:
            json.dump(self.doc, f, indent=1)
            f.write('\n')


def cornell(out_dir):
    g = Gltf()
    white = g.material('white', (0.725, 0.71, 0.68))
    red = g.material('red', (0.63, 0.065, 0.05))
    green = g.material('green', (0.14, 0.45, 0.091))
    # GAMES101 main.cpp builds the light's radiance from three blackbody-ish
    # lobes; glTF caps emissiveFactor at 1, so the peak goes into the strength.
    radiance = [round(8.0 * a + 15.6 * b + 18.4 * c, 6) for a, b, c in zip(
        (0.747 + 0.058, 0.747 + 0.258, 0.747),
        (0.740 + 0.287, 0.740 + 0.160, 0.740),
        (0.737 + 0.642, 0.737 + 0.159, 0.737))]  # (47.8348, 38.5664, 31.0808)
    strength = max(radiance)
    light = g.material('light', (0.65, 0.65, 0.65),
                       emissive=[round(r / strength, 6) for r in radiance],
                       strength=strength)

    # Vertex data as in GAMES101 models/cornellbox/*.obj. GAMES101 calls the red
    # wall (x~555) "left" because its camera puts it on the image's left.
    room = {
        'floor': (white, [(552.8, 0, 0), (0, 0, 0), (0, 0, 559.2), (549.6, 0, 559.2)]),
        'ceiling': (white, [(556, 548.8, 0), (556, 548.8, 559.2), (0, 548.8, 559.2),
                            (0, 548.8, 0)]),
        'backWall': (white, [(549.6, 0, 559.2), (0, 0, 559.2), (0, 548.8, 559.2),
                             (556, 548.8, 559.2)]),
        'leftWall': (red, [(552.8, 0, 0), (549.6, 0, 559.2), (556, 548.8, 559.2),
                           (556, 548.8, 0)]),
        'rightWall': (green, [(0, 0, 559.2), (0, 0, 0), (0, 548.8, 0), (0, 548.8, 559.2)]),
    }
    room_centre = (278.0, 274.0, 280.0)
    for name, (mat, quad) in room.items():
        g.mesh(name, orient_quads([quad], lambda p: sub(room_centre, p)), mat)

    # Sits 0.1 below the ceiling; must face down or it lights nothing.
    light_quad = [(343, 548.7, 227), (343, 548.7, 332), (213, 548.7, 332), (213, 548.7, 227)]
    light_tris = orient_quads([light_quad], lambda p: (0.0, -1.0, 0.0))
    assert abs(sum(tri_area(*t) for t in light_tris) - 130 * 105) < 1e-6
    g.mesh('light', light_tris, light)

    # Blocks have no bottom face (as in GAMES101); faces point away from the block centre.
    blocks = {
        'shortBox': [
            [(130, 165, 65), (82, 165, 225), (240, 165, 272), (290, 165, 114)],
            [(290, 0, 114), (290, 165, 114), (240, 165, 272), (240, 0, 272)],
            [(130, 0, 65), (130, 165, 65), (290, 165, 114), (290, 0, 114)],
            [(82, 0, 225), (82, 165, 225), (130, 165, 65), (130, 0, 65)],
            [(240, 0, 272), (240, 165, 272), (82, 165, 225), (82, 0, 225)]],
        'tallBox': [
            [(423, 330, 247), (265, 330, 296), (314, 330, 456), (472, 330, 406)],
            [(423, 0, 247), (423, 330, 247), (472, 330, 406), (472, 0, 406)],
            [(472, 0, 406), (472, 330, 406), (314, 330, 456), (314, 0, 456)],
            [(314, 0, 456), (314, 330, 456), (265, 330, 296), (265, 0, 296)],
            [(265, 0, 296), (265, 330, 296), (423, 330, 247), (423, 0, 247)]],
    }
    for name, quads in blocks.items():
        centre = centroid([p for q in quads for p in q])
        g.mesh(name, orient_quads(quads, lambda p, c=centre: sub(p, c)), white)

    # GAMES101: eye (278,273,-800), 40 deg vertical fov, looking down +Z.
    # glTF cameras look down local -Z, hence the 180 deg turn about Y.
    g.camera(math.radians(40.0), translation=(278.0, 273.0, -800.0), rotation=(0.0, 1.0, 0.0, 0.0))
    g.save(out_dir, 'cornell')


def icosphere(levels):
    """Unit icosphere: an icosahedron with every triangle split in four `levels`
    times and the new vertices pushed onto the sphere."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
             (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    unit = lambda p: tuple(c / math.sqrt(dot(p, p)) for c in p)
    tris = [tuple(unit(verts[i]) for i in f) for f in (
        (0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
        (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
        (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1))]
    for _ in range(levels):
        finer = []
        for a, b, c in tris:
            ab, bc, ca = (unit(centroid([p, q])) for p, q in ((a, b), (b, c), (c, a)))
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        tris = finer
    return tris


def furnace(out_dir):
    # Inside a closed enclosure of one material with emission Le and albedo rho,
    # L = Le + rho*L everywhere, so L = Le / (1 - rho) exactly.
    # The enclosure is a sphere (a 1280-triangle icosphere), not a cube: inside a
    # sphere the light-sampling weight cos(theta) cos(theta') / r^2 is the constant
    # 1 / (4 R^2), so next-event estimation has finite variance and a z-test on the
    # render's own variance is valid. In a cube's concave edges that weight is
    # unbounded (infinite variance), and sample means converge slowly from below.
    albedo, emission = (0.3, 0.5, 0.8), (0.5, 0.5, 0.5)
    expected = [round(e / (1.0 - a), 9) for e, a in zip(emission, albedo)]
    g = Gltf(extras={'expectedRadiance': expected, 'albedo': list(albedo),
                     'emission': list(emission)})
    mat = g.material('furnace', albedo, emissive=emission)
    inward = []
    for tri in icosphere(3):
        # Front faces point at the centre.
        if dot(tri_normal(*tri), centroid(tri)) > 0:
            tri = (tri[0], tri[2], tri[1])
        assert dot(tri_normal(*tri), centroid(tri)) < 0
        inward.append(tri)
    g.mesh('enclosure', inward, mat)
    g.camera(1.2)
    g.save(out_dir, 'furnace')


def many_lights(out_dir):
    # A 40 x 6 x 20 hall with pillars, lit only by 1,000 small quads (2,000 emissive
    # triangles, 6 to 20 cm wide) hung at varied heights and tilts, of radiances spread
    # over 128x: from any
    # point most of the light comes from a few nearby quads, which choosing by power
    # alone rarely picks. A fixed linear congruential generator places them, so the
    # file is the same on every machine.
    state = [12345]

    def rand():
        state[0] = (state[0] * 1103515245 + 12345) % 2**31
        return state[0] / 2**31

    g = Gltf()
    wall = g.material('wall', (0.7, 0.7, 0.7))
    floor = g.material('floor', (0.5, 0.45, 0.4))
    pillar = g.material('pillar', (0.6, 0.3, 0.2))
    tints = [(1.0, 0.85, 0.6), (0.7, 0.8, 1.0), (1.0, 1.0, 1.0), (1.0, 0.6, 0.5)]
    lamps = [g.material('lamp%d' % k, (0.8, 0.8, 0.8), emissive=tints[k % 4], strength=2.0 ** (k + 1))
             for k in range(8)]
    W, H, D = 40.0, 6.0, 20.0
    centre = (W / 2, H / 2, D / 2)
    g.mesh('floor', orient_quads([[(0, 0, 0), (W, 0, 0), (W, 0, D), (0, 0, D)]],
                                 lambda p: (0.0, 1.0, 0.0)), floor)
    shell = [[(0, H, 0), (W, H, 0), (W, H, D), (0, H, D)],
             [(0, 0, 0), (W, 0, 0), (W, H, 0), (0, H, 0)], [(0, 0, D), (W, 0, D), (W, H, D), (0, H, D)],
             [(0, 0, 0), (0, 0, D), (0, H, D), (0, H, 0)], [(W, 0, 0), (W, 0, D), (W, H, D), (W, H, 0)]]
    g.mesh('walls', orient_quads(shell, lambda p: sub(centre, p)), wall)
    pillars = []
    for i in range(7):
        for j in range(2):
            x, z, r = 5.0 * (i + 1), 6.5 + 7.0 * j, 0.4
            c = (x, H / 2, z)
            pillars += orient_quads([[(x - r, 0, z - r), (x + r, 0, z - r), (x + r, H, z - r), (x - r, H, z - r)],
                                     [(x - r, 0, z + r), (x + r, 0, z + r), (x + r, H, z + r), (x - r, H, z + r)],
                                     [(x - r, 0, z - r), (x - r, 0, z + r), (x - r, H, z + r), (x - r, H, z - r)],
                                     [(x + r, 0, z - r), (x + r, 0, z + r), (x + r, H, z + r), (x + r, H, z - r)]],
                                    lambda p, c=c: sub(p, (c[0], p[1], c[2])))
    g.mesh('pillars', pillars, pillar)
    quads = [[] for _ in lamps]
    for k in range(1000):
        x, z = 0.5 + (W - 1.0) * rand(), 0.5 + (D - 1.0) * rand()
        y, size = 2.5 + 3.3 * rand(), 0.03 + 0.07 * rand()
        # Facing down, tilted up to 60 degrees about a random horizontal axis.
        tilt, turn = math.radians(60.0) * rand(), 2.0 * math.pi * rand()
        n = (math.sin(tilt) * math.cos(turn), -math.cos(tilt), math.sin(tilt) * math.sin(turn))
        u = cross(n, (0.0, 0.0, 1.0))
        u = tuple(c / math.sqrt(dot(u, u)) for c in u)
        v = cross(n, u)
        corner = lambda a, b: tuple(c + size * (a * uu + b * vv) for c, uu, vv in zip((x, y, z), u, v))
        quad = [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)]
        quads[int(8 * rand())].append(orient_quads([quad], lambda p, n=n: n))
    for k, lamp in enumerate(lamps):
        g.mesh('lamps%d' % k, [t for q in quads[k] for t in q], lamp)
    # At one end of the hall, looking along it (glTF cameras look down local -Z).
    g.camera(math.radians(60.0), translation=(2.0, 1.7, D / 2), rotation=(0.0, -0.7071068, 0.0, 0.7071068))
    g.save(out_dir, 'many_lights')


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--out', default=os.path.dirname(os.path.abspath(__file__)),
                    help='output directory (default: next to this script)')
    out_dir = ap.parse_args().out
    os.makedirs(out_dir, exist_ok=True)
    cornell(out_dir)
    furnace(out_dir)
    many_lights(out_dir)


if __name__ == '__main__':
    main()
