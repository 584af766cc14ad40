// Ray casts (tests/ray.rs): mj_ray from a grid of points in many directions against
// models/extra/ray_scene.xml (every geom type), with group filters, static geoms off and a body
// excluded; mju_rayGeom on every primitive, also with a zero direction; mj_rayMesh and
// mj_rayHfield. Prints geom ids and the distances' bits, identical on both libraries.
#include <mujoco/mujoco.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static uint64_t bits(mjtNum x) {
  uint64_t u;
  memcpy(&u, &x, sizeof u);
  return u;
}

int main(int argc, char** argv) {
  char err[1000] = "";
  mjModel* m = mj_loadXML(argv[1], NULL, err, sizeof err);
  if (!m) {
    printf("error: %s\n", err);
    return 1;
  }
  mjData* d = mj_makeData(m);
  mj_forward(m, d);
  const mjtByte groups[3][6] = {{1, 1, 1, 1, 1, 1}, {1, 0, 1, 0, 1, 0}, {0, 1, 0, 1, 0, 1}};
  const mjtNum scales[4] = {1, 1e-8, 1e6, 1e160};  // direction lengths
  uint64_t hash = 14695981039346656037ull;
  int hits = 0, casts = 0;
  for (int ix = -4; ix <= 4; ix++) {
    for (int iy = -4; iy <= 4; iy++) {
      for (int iz = -1; iz <= 2; iz++) {
        mjtNum pnt[3] = {0.37 * ix, 0.29 * iy, 0.45 * iz};
        for (int k = 0; k < 26; k++) {
          // directions towards the cube's corners, edges and faces, slightly skewed
          int a = k < 13 ? k : k + 1;
          mjtNum vec[3] = {a % 3 - 1 + 0.01 * k, (a / 3) % 3 - 1 - 0.007 * k, a / 9 - 1 + 0.003};
          mjtNum s = scales[(ix + iy + k) & 3];
          for (int j = 0; j < 3; j++) vec[j] *= s;
          int variant = (ix * 7 + iy * 3 + iz + k + 100) % 5;
          const mjtByte* gr = variant < 3 ? groups[variant] : NULL;
          mjtByte with_static = variant != 3;
          int exclude = variant == 4 ? 1 + (k & 1) : -1;
          int geomid = -2;
          mjtNum x = mj_ray(m, d, pnt, vec, gr, with_static, exclude, &geomid);
          casts++;
          hits += geomid >= 0;
          uint64_t v[2] = {bits(x), (uint64_t)(int64_t)geomid};
          for (int b = 0; b < 16; b++) hash = (hash ^ ((unsigned char*)v)[b]) * 1099511628211ull;
          if (k == 0 && iz == 0) printf("ray %2d %2d: geom %2d dist %016llx\n", ix, iy, geomid,
                                        (unsigned long long)bits(x));
        }
      }
    }
  }
  printf("mj_ray: %d casts, %d hits, hash %016llx\n", casts, hits, (unsigned long long)hash);

  // each primitive alone, from points around it, and a zero direction
  for (int g = 0; g < m->ngeom; g++) {
    int t = m->geom_type[g];
    mjtNum* p = d->geom_xpos + 3 * g;
    for (int k = 0; k < 8; k++) {
      mjtNum pnt[3] = {p[0] + (k & 1 ? 0.5 : -0.4), p[1] + (k & 2 ? 0.45 : -0.35), p[2] + 0.3};
      mjtNum vec[3] = {p[0] - pnt[0], p[1] - pnt[1] + 0.01 * k, p[2] - pnt[2]};
      if (k == 7) vec[0] = vec[1] = vec[2] = 0;
      mjtNum x;
      if (t == mjGEOM_MESH) {
        x = mj_rayMesh(m, d, g, pnt, vec);
      } else if (t == mjGEOM_HFIELD) {
        x = mj_rayHfield(m, d, g, pnt, vec);
      } else {
        x = mju_rayGeom(p, d->geom_xmat + 9 * g, m->geom_size + 3 * g, pnt, vec, t);
      }
      printf("geom %2d type %d from %d: %016llx\n", g, t, k, (unsigned long long)bits(x));
    }
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
