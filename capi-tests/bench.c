// Simulation speed, built against each library (tests/speed.rs; capi-tests/bench also against
// MuJoCo 4.0.0):
//   bench STEPS DISABLEFLAGS FILE [stages]   loads FILE, ors DISABLEFLAGS into
//   opt.disableflags, resets (keyframe 0 if any), and times STEPS driven mj_step calls after 100
//   warm-up steps; prints "steps/s <rate>", or "error <message>" when the library stops with
//   mju_error. With "stages", STEPS more steps follow with the library's stage timers on
//   (mjcb_time): "stage <name> <microseconds per step>" for each timer, then the work a step
//   did on average: "count <name> <value>" for contacts, constraint rows and solver iterations
//   (MuJoCo 4.0.0 solves each constraint island on its own: its iterations summed over the
//   islands, the largest island's, and the number of islands).
#include "child.h"  // first: it sets the feature macros
#include <stdlib.h>
#include <string.h>
#include <time.h>

static void on_error(const char* msg) {
  printf("error %s\n", msg);
  exit(0);
}

static void quiet(const char* msg) { (void)msg; }

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static mjtNum now_us(void) { return 1e6 * now(); }

// STEPS more driven steps with the stage timers on; microseconds per step of each timer. The
// timers are collected after every step: a model that goes unstable is reset by the library
// (mj_resetData), which clears d->timer.
static void stages(const mjModel* m, mjData* d, int steps) {
  mjtNum sum[mjNTIMER] = {0};
  double ncon = 0, nefc = 0, iter = 0;
#if mjVERSION_HEADER >= 300
  double islands = 0, largest = 0;
#endif
  mjcb_time = now_us;
  for (int i = 0; i < mjNTIMER; i++) d->timer[i].duration = 0;
  for (int s = 0; s < steps; s++) {
    drive_controls(m, d, s);
    mj_step(m, d);
    for (int i = 0; i < mjNTIMER; i++) {
      sum[i] += d->timer[i].duration;
      d->timer[i].duration = 0;
    }
    ncon += d->ncon;
    nefc += d->nefc;
#if mjVERSION_HEADER >= 300
    int n = d->nisland < mjNISLAND ? d->nisland : mjNISLAND, most = 0;
    for (int k = 0; k < (n > 0 ? n : 1); k++) {
      iter += d->solver_niter[k];
      most = d->solver_niter[k] > most ? d->solver_niter[k] : most;
    }
    islands += d->nisland;
    largest += most;
#else
    iter += d->solver_iter;
#endif
  }
  for (int i = 0; i < mjNTIMER; i++) {
    printf("stage %s %.3f\n", mjTIMERSTRING[i], sum[i] / steps);
  }
  printf("count contacts %.2f\n", ncon / steps);
  printf("count constraint rows %.2f\n", nefc / steps);
  printf("count solver iterations %.2f\n", iter / steps);
#if mjVERSION_HEADER >= 300
  printf("count islands %.2f\n", islands / steps);
  printf("count largest island iterations %.2f\n", largest / steps);
#endif
}

int main(int argc, char** argv) {
  if (argc != 4 && !(argc == 5 && !strcmp(argv[4], "stages"))) {
    fprintf(stderr, "usage: bench STEPS DISABLEFLAGS FILE [stages]\n");
    return 2;
  }
  mju_user_error = on_error;
  mju_user_warning = quiet;  // unstable runs reset and go on in both libraries
  int steps = atoi(argv[1]);
  char err[1000] = "";
  mjModel* m = mj_loadXML(argv[3], NULL, err, sizeof err);
  if (!m) {
    printf("error %s\n", err);
    return 0;
  }
  m->opt.disableflags |= atoi(argv[2]);
  mjData* d = mj_makeData(m);
  if (m->nkey > 0) mj_resetDataKeyframe(m, d, 0);
  for (int s = 0; s < 100; s++) {
    drive_controls(m, d, s);
    mj_step(m, d);
  }
  double t0 = now();
  for (int s = 0; s < steps; s++) {
    drive_controls(m, d, s);
    mj_step(m, d);
  }
  double dt = now() - t0;
  printf("steps/s %.1f\n", steps / dt);
  if (argc == 5) stages(m, d, steps);
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
