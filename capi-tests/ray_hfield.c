// Rays against height fields (tests/ray.rs): models/extra/ray_hfield.xml with its heights
// filled from a fixed sequence, then mj_rayHfield and mj_ray from a grid of points above,
// inside, beside and below the fields, in directions from a fixed sequence plus axis-aligned,
// vertical and grazing ones. Prints the counts and a hash of the distance bits, identical on
// both libraries.
#include <mujoco/mujoco.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static uint64_t state = 88172645463325252ull;

// uniform in [-1, 1)
static double next(void) {
  state ^= state << 13;
  state ^= state >> 7;
  state ^= state << 17;
  return (double)(state >> 11) / 4503599627370496.0 - 1.0;
}

static uint64_t hash = 14695981039346656037ull;

static void mix(mjtNum x) {
  unsigned char b[8];
  memcpy(b, &x, 8);
  for (int i = 0; i < 8; i++) hash = (hash ^ b[i]) * 1099511628211ull;
}

int main(int argc, char** argv) {
  char err[1000] = "";
  mjModel* m = mj_loadXML(argv[1], NULL, err, sizeof err);
  if (!m) {
    printf("error: %s\n", err);
    return 1;
  }
  // bumpy heights in [0, 1]: smooth waves plus noise, a flat patch and a spike
  for (int h = 0; h < m->nhfield; h++) {
    int nrow = m->hfield_nrow[h], ncol = m->hfield_ncol[h];
    float* data = m->hfield_data + m->hfield_adr[h];
    for (int r = 0; r < nrow; r++) {
      for (int c = 0; c < ncol; c++) {
        double v = 0.5 + 0.25 * next() + 0.2 * (r % 7 == 0) - 0.15 * (c % 5 == 2);
        if (r > nrow / 2 && c > ncol / 2 && r < nrow / 2 + 4 && c < ncol / 2 + 4) v = 0.3;
        if (r == nrow / 3 && c == ncol / 3) v = 1;
        data[r * ncol + c] = (float)(v < 0 ? 0 : v > 1 ? 1 : v);
      }
    }
  }
  mjData* d = mj_makeData(m);
  mj_forward(m, d);
  const mjtNum fixed[][3] = {
      {0, 0, -1}, {1, 0, 0},  {0, 1, 0},      {-1, 0, -1e-9}, {1e-9, 1, -0.05}, {1, 1e-12, -0.02},
      {0, 0, 1},  {1, 1, -1}, {3, -1, -0.1}, {-1, 1e-7, -0.3}, {1e-15, -1, -1e-3}, {0, 0, 0}};
  int nfixed = sizeof fixed / sizeof fixed[0];
  int casts = 0, hits = 0;
  for (int ix = -7; ix <= 7; ix++) {
    for (int iy = -5; iy <= 5; iy++) {
      for (int iz = -1; iz <= 3; iz++) {
        mjtNum pnt[3] = {0.45 * ix + 0.013, 0.41 * iy - 0.007, 0.35 * iz + 0.05};
        for (int k = 0; k < nfixed + 14; k++) {
          mjtNum vec[3];
          if (k < nfixed) {
            memcpy(vec, fixed[k], sizeof vec);
          } else {
            vec[0] = next();
            vec[1] = next();
            vec[2] = next() - 0.4;
          }
          mjtNum s = k % 3 == 0 ? 1 : k % 3 == 1 ? 1e-5 : 1e4;
          for (int j = 0; j < 3; j++) vec[j] *= s;
          for (int g = 0; g < m->ngeom; g++) {
            mjtNum x = mj_rayHfield(m, d, g, pnt, vec);
            casts++;
            hits += x >= 0;
            mix(x);
          }
          if (vec[0] == 0 && vec[1] == 0 && vec[2] == 0) continue;  // mj_ray stops on it
          int geomid = -2;
          mjtNum x = mj_ray(m, d, pnt, vec, NULL, 1, -1, &geomid);
          mix(x);
          mix(geomid);
        }
      }
    }
  }
  printf("mj_rayHfield: %d casts, %d hits, hash %016llx\n", casts, hits,
         (unsigned long long)hash);
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
