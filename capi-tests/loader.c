// Loader checks, built against each library (tests/loader.rs):
//   loader verdict FILE...   one line per file: "load <sizes>", "reject <message>",
//                            "crash <signal>" or "hang" (each load in a child, 20 s limit)
//   loader time FILE...      loads each file once; one line per file: the seconds taken, or
//                            "-1" when it does not load
//   loader mjbsave DIR FILE...  saves each file's model as DIR/<index>.mjb; one line per file:
//                            that path, or "-" when it does not load
//   loader mjbtime FILE...   mj_loadModel of each MJB file once, as `time`
#include "child.h"  // first: it sets the feature macros
#include <stdlib.h>
#include <string.h>
#include <time.h>


static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// The first line of the message, with the file's directory left out (paths differ by run).
static void one_line(char* s) {
  for (char* p = s; *p; p++) {
    if (*p == '\n' || *p == '\r') {
      *p = 0;
      break;
    }
  }
}

// One line: the sizes of the loaded model, or the first line of the error.
static void load_one(const char* file) {
  char err[1000] = "";
  mjModel* m = mj_loadXML(file, NULL, err, sizeof err);
  if (m) {
    printf("load nq=%d nv=%d nu=%d na=%d nbody=%d njnt=%d ngeom=%d nsite=%d nmesh=%d ntendon=%d "
           "nsensor=%d neq=%d nkey=%d\n",
           m->nq, m->nv, m->nu, m->na, m->nbody, m->njnt, m->ngeom, m->nsite, m->nmesh,
           m->ntendon, m->nsensor, m->neq, m->nkey);
    mj_deleteModel(m);
  } else {
    one_line(err);
    printf("reject %s\n", err);
  }
}

static void quiet(const char* msg) { (void)msg; }

int main(int argc, char** argv) {
  if (argc >= 3 && !strcmp(argv[1], "verdict")) {
    mju_user_warning = quiet;
    for (int i = 2; i < argc; i++) in_child(load_one, argv[i], 20);
    return 0;
  }
  if (argc >= 3 && !strcmp(argv[1], "time")) {
    mju_user_warning = quiet;
    for (int i = 2; i < argc; i++) {
      char err[1000] = "";
      double t0 = now();
      mjModel* m = mj_loadXML(argv[i], NULL, err, sizeof err);
      double t = now() - t0;
      printf("%.6f\n", m ? t : -1.0);
      mj_deleteModel(m);
    }
    return 0;
  }
  if (argc >= 3 && !strcmp(argv[1], "mjbsave")) {
    mju_user_warning = quiet;
    for (int i = 3; i < argc; i++) {
      char err[1000] = "", path[4096];
      mjModel* m = mj_loadXML(argv[i], NULL, err, sizeof err);
      snprintf(path, sizeof path, "%s/%d.mjb", argv[2], i - 3);
      if (m) mj_saveModel(m, path, NULL, 0);
      printf("%s\n", m ? path : "-");
      mj_deleteModel(m);
    }
    return 0;
  }
  if (argc >= 3 && !strcmp(argv[1], "mjbtime")) {
    mju_user_warning = quiet;
    for (int i = 2; i < argc; i++) {
      double t0 = now();
      mjModel* m = mj_loadModel(argv[i], NULL);
      double t = now() - t0;
      printf("%.6f\n", m ? t : -1.0);
      mj_deleteModel(m);
    }
    return 0;
  }
  fprintf(stderr, "usage: loader verdict FILE... | loader time FILE... | loader mjbsave DIR FILE... | "
                  "loader mjbtime FILE...\n");
  return 2;
}
