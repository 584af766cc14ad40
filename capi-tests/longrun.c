// Long runs, built against each library (tests/long_run.rs):
//   longrun STEPS FILE...   per file, in a child process: load, then STEPS driven mj_step calls
//   (a fifth of them for models of more than BIG bodies or BIG_NV dofs: composites, crowds of
//   humanoids, stacks of free bodies, long chains);
//   one line per file: "ok nan=<first step with a NaN or -1> warnings=<type:count,...>",
//   "load-error <message>", "error <mju_error message>", "crash <signal>" or "hang"
#include "child.h"  // first: it sets the feature macros
#include <stdlib.h>
#include <string.h>

static void on_error(const char* msg) {
  char line[600];
  snprintf(line, sizeof line, "%s", msg);
  for (char* p = line; *p; p++)
    if (*p == '\n') *p = ' ';
  printf("error %s\n", line);
  fflush(stdout);
  _exit(0);
}

static void quiet(const char* msg) { (void)msg; }

static int has_nan(const mjtNum* x, int n) {
  for (int i = 0; i < n; i++)
    if (isnan(x[i]) || isinf(x[i])) return 1;
  return 0;
}

static int steps = 0;
#define BIG 100
#define BIG_NV 60
#define BIG_HFIELD 10000

// a fifth of the steps: many bodies or dofs, or a large height field (the slowest collisions)
static int big(const mjModel* m) {
  if (m->nbody > BIG || m->nv > BIG_NV) return 1;
  for (int i = 0; i < m->nhfield; i++)
    if (m->hfield_nrow[i] * m->hfield_ncol[i] > BIG_HFIELD) return 1;
  return 0;
}

static void run(const char* file) {
  char err[1000] = "";
  mjModel* m = mj_loadXML(file, NULL, err, sizeof err);
  if (!m) {
    for (char* p = err; *p; p++)
      if (*p == '\n') *p = ' ';
    printf("load-error %s\n", err);
    return;
  }
  mjData* d = mj_makeData(m);
  if (m->nkey > 0) mj_resetDataKeyframe(m, d, 0);
  int nan_at = -1, n = big(m) ? steps / 5 : steps;
  for (int s = 0; s < n; s++) {
    drive_controls(m, d, s);
    mj_step(m, d);
    if (nan_at < 0 && (has_nan(d->qpos, m->nq) || has_nan(d->qvel, m->nv) || has_nan(d->qacc, m->nv)))
      nan_at = s;
  }
  printf("ok nan=%d warnings=", nan_at);
  for (int k = 0; k < mjNWARNING; k++)
    if (d->warning[k].number) printf("%d:%d,", k, d->warning[k].number);
  printf("\n");
}

int main(int argc, char** argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: longrun STEPS FILE...\n");
    return 2;
  }
  steps = atoi(argv[1]);
  mju_user_error = on_error;
  mju_user_warning = quiet;
  for (int i = 2; i < argc; i++) in_child(run, argv[i], 120);
  return 0;
}
