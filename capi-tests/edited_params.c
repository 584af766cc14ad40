// Contact parameters a program edits in mjModel, NaN among them (tests/edited_params.rs): a
// NaN margin, gap, friction or direct solref, or a size edited to zero or NaN, on one geom and
// then on another, a NaN impratio and a NaN gravity, the model run for 60 steps. 2.2.2 mixes a pair's parameters with mju_max/mju_min, which pass a NaN on in
// one argument order only, and its collision filters then test with that margin. Prints the
// contacts (every field, byte for byte) and the state as hashes, identical on both libraries.
#include <math.h>
#include <mujoco/mujoco.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static uint64_t hash(uint64_t h, const void* p, size_t n) {
  const unsigned char* b = p;
  for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ull;
  return h;
}

static void quiet(const char* msg) { (void)msg; }

// One edit of geom g: 0 margin, 1 gap, 2 friction (sliding), 3 solref (direct, NaN damping),
// 4 size: a zero third half-size (a box's, which box routines take as no bound), 5 size: a
// NaN first one (the bounding radius stays as compiled).
static void edit(mjModel* m, int kind, int g) {
  switch (kind) {
    case 0: m->geom_margin[g] = NAN; break;
    case 1: m->geom_gap[g] = NAN; break;
    case 2: m->geom_friction[3 * g] = NAN; break;
    case 4: m->geom_size[3 * g + 2] = 0; break;
    case 5: m->geom_size[3 * g] = NAN; break;
    default:
      m->geom_solref[mjNREF * g] = -100;
      m->geom_solref[mjNREF * g + 1] = NAN;
  }
}

static void run(const mjModel* m, mjData* d, const char* what) {
  mj_resetData(m, d);
  uint64_t h = 14695981039346656037ull;
  int ncon = 0;
  for (int s = 0; s < 60; s++) {
    for (int i = 0; i < m->nu; i++) d->ctrl[i] = 0.3 * sin(0.1 * s + i);
    mj_step(m, d);
    ncon += d->ncon;
    h = hash(h, d->contact, sizeof(mjContact) * d->ncon);
    h = hash(h, d->qacc, sizeof(mjtNum) * m->nv);
    h = hash(h, d->qpos, sizeof(mjtNum) * m->nq);
  }
  printf("%-34s contacts %5d hash %016llx\n", what, ncon, (unsigned long long)h);
}

int main(int argc, char** argv) {
  mju_user_warning = quiet;
  const char* kinds[] = {"margin NaN", "gap NaN", "friction NaN", "solref NaN",
                         "size[2] zero", "size[0] NaN"};
  for (int a = 1; a < argc; a++) {
    char err[1000];
    mjModel* m = mj_loadXML(argv[a], NULL, err, sizeof err);
    if (!m) {
      printf("%s: %s\n", argv[a], err);
      return 1;
    }
    mjData* d = mj_makeData(m);
    const char* name = strrchr(argv[a], '/') ? strrchr(argv[a], '/') + 1 : argv[a];
    printf("%s\n", name);
    run(m, d, "as loaded");
    // geoms that collide: the first, others through the model, and the last
    int picks[5], npick = 0, last = m->ngeom - 1;
    for (int g = 0; g < m->ngeom && npick < 4; g += 1 + m->ngeom / 5) {
      if (m->geom_contype[g] || m->geom_conaffinity[g]) picks[npick++] = g;
    }
    while (last >= 0 && !m->geom_contype[last] && !m->geom_conaffinity[last]) last--;
    if (last >= 0 && (npick == 0 || picks[npick - 1] != last)) picks[npick++] = last;
    for (int p = 0; p < npick; p++) {
      int g = picks[p];
      for (int k = 0; k < 6; k++) {
        mjModel* e = mj_copyModel(NULL, m);
        edit(e, k, g);
        char what[64];
        snprintf(what, sizeof what, "%s on geom %d", kinds[k], g);
        run(e, d, what);
        mj_deleteModel(e);
      }
    }
    // the option that divides R for elliptic cones (2.2.2: mju_max(mjMINVAL, impratio))
    mjModel* e = mj_copyModel(NULL, m);
    e->opt.impratio = NAN;
    run(e, d, "impratio NaN");
    mj_deleteModel(e);
    // gravity, which 2.2.2 scales by -1 (a NaN keeps its sign)
    e = mj_copyModel(NULL, m);
    e->opt.gravity[2] = NAN;
    run(e, d, "gravity NaN");
    mj_deleteModel(e);
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  return 0;
}
