// Loader checks, built against each library (tests/loader.rs):
//   loader verdict FILE...   one line per file: "load <sizes>", "reject <message>",
//                            "crash <signal>" or "hang" (each load in a child, 20 s limit)
//   loader time N FILE...    loads every file N times; prints the seconds taken
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
  if (argc >= 4 && !strcmp(argv[1], "time")) {
    int reps = atoi(argv[2]);
    double t0 = now();
    for (int k = 0; k < reps; k++) {
      for (int i = 3; i < argc; i++) {
        char err[1000] = "";
        mjModel* m = mj_loadXML(argv[i], NULL, err, sizeof err);
        if (!m) {
          fprintf(stderr, "%s: %s\n", argv[i], err);
          return 1;
        }
        mj_deleteModel(m);
      }
    }
    printf("%.6f\n", now() - t0);
    return 0;
  }
  fprintf(stderr, "usage: loader verdict FILE... | loader time N FILE...\n");
  return 2;
}
