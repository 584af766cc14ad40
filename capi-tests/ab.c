// Step time of two libraries in one process (capi-tests/bench --ab; tests/speed.rs):
//   ab LIB_A LIB_B MODEL BLOCK ROUNDS [DISABLEFLAGS [OFFSET_B]]
// dlopens both libraries (each with its own symbols), loads MODEL in each, ors DISABLEFLAGS into
// opt.disableflags (at 2.2.2's offset, or OFFSET_B for library B), silences warnings, takes 100
// steps, then times ROUNDS rounds of BLOCK mj_step calls per library, alternating which goes
// first. A slow spell of the machine hits both alike, so the ratio holds where whole-process
// timings swing.
// Built without linking any MuJoCo (gcc -I include ab.c -ldl), so that neither library's
// symbols are in the global scope. Prints "ab <ns A min> <ns A median> <ns B min> <ns B median>" per step, or "error <message>".
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <mujoco/mujoco.h>

typedef mjModel* (*load_fn)(const char*, const mjVFS*, char*, int);
typedef mjData* (*make_fn)(const mjModel*);
typedef void (*step_fn)(const mjModel*, mjData*);

struct lib {
  mjModel* m;
  mjData* d;
  step_fn step;
};

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int by_value(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

static void quiet(const char* msg) { (void)msg; }

static int open_lib(struct lib* l, const char* path, const char* model, int flags, size_t off) {
  void* h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
  if (!h) {
    printf("error %s\n", dlerror());
    return 0;
  }
  load_fn load = (load_fn)dlsym(h, "mj_loadXML");
  make_fn make = (make_fn)dlsym(h, "mj_makeData");
  l->step = (step_fn)dlsym(h, "mj_step");
  if (!load || !make || !l->step) {
    printf("error %s: no mj_loadXML, mj_makeData or mj_step\n", path);
    return 0;
  }
  // warnings silenced in both, as in bench.c: unstable runs reset and go on, and the output
  // stays one line
  void (**warn)(const char*) = (void (**)(const char*))dlsym(h, "mju_user_warning");
  if (warn) *warn = quiet;
  char err[1000] = "";
  l->m = load(model, NULL, err, sizeof err);
  if (!l->m) {
    printf("error %s\n", err);
    return 0;
  }
  *(int*)((char*)l->m + off) |= flags;
  l->d = make(l->m);
  for (int s = 0; s < 100; s++) l->step(l->m, l->d);
  return 1;
}

int main(int argc, char** argv) {
  if (argc < 6 || argc > 8) {
    fprintf(stderr, "usage: ab LIB_A LIB_B MODEL BLOCK ROUNDS [DISABLEFLAGS [OFFSET_B]]\n");
    return 2;
  }
  int block = atoi(argv[4]), rounds = atoi(argv[5]);
  int flags = argc > 6 ? atoi(argv[6]) : 0;
  size_t off = offsetof(mjModel, opt) + offsetof(mjOption, disableflags);
  size_t off_b = argc > 7 ? (size_t)atol(argv[7]) : off;
  if (block < 1 || rounds < 1) {
    fprintf(stderr, "ab: BLOCK and ROUNDS must be positive\n");
    return 2;
  }
  struct lib l[2];
  if (!open_lib(&l[0], argv[1], argv[3], flags, off) ||
      !open_lib(&l[1], argv[2], argv[3], flags, off_b))
    return 0;
  if (l[0].step == l[1].step) {
    printf("error the two paths are one library\n");
    return 0;
  }
  double* t[2] = {malloc(sizeof(double) * rounds), malloc(sizeof(double) * rounds)};
  for (int r = 0; r < rounds; r++) {
    for (int k = 0; k < 2; k++) {
      int i = (r & 1) ? 1 - k : k;
      double t0 = now();
      for (int s = 0; s < block; s++) l[i].step(l[i].m, l[i].d);
      t[i][r] = (now() - t0) / block * 1e9;
    }
  }
  for (int i = 0; i < 2; i++) qsort(t[i], rounds, sizeof(double), by_value);
  printf("ab %.1f %.1f %.1f %.1f\n", t[0][0], t[0][rounds / 2], t[1][0], t[1][rounds / 2]);
  return 0;
}
