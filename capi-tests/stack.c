// The mjData stack on both libraries: maxuse_stack after a driven trajectory and after each
// stage and API function that takes scratch, and the point where the stack overflows.
//   stack MODEL [DISABLEFLAGS]
// prints one line of name=value pairs (or "load-error"). The stage values are measured with
// maxuse_stack cleared before each call. Overflow: the trajectory's first 20 steps run again
// with nstack set to the high-water mark they reached (must pass) and one below (must stop
// with the reference's error message), each in a child process. The callbacks' view of the
// stack top: calls, sum and maximum of pstack per callback over one mj_forward and mj_step.

#define _DEFAULT_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <mujoco/mujoco.h>

// An error ends the line (2.2.2 would go on after a returning handler with a bad pointer).
static void on_error(const char* msg) {
  printf(" error=%s\n", msg);
  fflush(stdout);
  _exit(0);
}

// In the overflow children: the message, then exit code 3.
static void on_child_error(const char* msg) {
  printf(" (%s)", msg);
  fflush(stdout);
  _exit(3);
}

static void on_warning(const char* msg) { (void)msg; }

static void drive(const mjModel* m, mjData* d) {
  mjtNum t = d->time;
  for (int i = 0; i < m->nu; i++) {
    mjtNum s = sin(2 * mjPI * (0.5 + 0.3 * i) * t + i);
    if (m->actuator_ctrllimited[i]) {
      mjtNum lo = m->actuator_ctrlrange[2 * i], hi = m->actuator_ctrlrange[2 * i + 1];
      d->ctrl[i] = lo + (hi - lo) * (0.5 + 0.4 * s);
    } else {
      d->ctrl[i] = 0.5 * s;
    }
  }
  for (int i = 0; i < m->nv; i++) d->qfrc_applied[i] = 0.02 * sin(1.3 * t + i);
  for (int b = 1; b < m->nbody; b++) {
    d->xfrc_applied[6 * b + 0] = 0.05 * cos(t + b);
    d->xfrc_applied[6 * b + 5] = 0.01 * sin(2 * t + b);
  }
}

static void start(const mjModel* m, mjData* d) {
  mj_resetData(m, d);
  if (m->nkey > 0) mj_resetDataKeyframe(m, d, 0);
}

// 20 driven steps with the given stack size, in a child: 1 if they run, 0 if an error stops
// them (its message printed).
static int steps_with_stack(mjModel* m, int nstack) {
  fflush(stdout);
  pid_t pid = fork();
  if (pid == 0) {
    mju_user_error = on_child_error;
    m->nstack = nstack;
    mjData* d = mj_makeData(m);
    if (!d) _exit(4);
    start(m, d);
    for (int k = 0; k < 20; k++) {
      drive(m, d);
      mj_step(m, d);
    }
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// The stack top the callbacks see: per callback, calls and the sum and maximum of pstack.
enum { CB_CONTROL, CB_PASSIVE, CB_FILTER, CB_GAIN, CB_BIAS, CB_DYN, CB_SENSOR, NCB };
static const char* cb_name[NCB] = {"control", "passive", "contactfilter", "act_gain",
                                   "act_bias", "act_dyn", "sensor"};
static long cb_count[NCB], cb_sum[NCB];
static int cb_max[NCB];

static void seen(int cb, const mjData* d) {
  cb_count[cb]++;
  cb_sum[cb] += d->pstack;
  if (d->pstack > cb_max[cb]) cb_max[cb] = d->pstack;
}
static void cb_control(const mjModel* m, mjData* d) { (void)m; seen(CB_CONTROL, d); }
static void cb_passive(const mjModel* m, mjData* d) { (void)m; seen(CB_PASSIVE, d); }
static int cb_filter(const mjModel* m, mjData* d, int g1, int g2) {
  (void)m, (void)g1, (void)g2;
  seen(CB_FILTER, d);
  return 0;
}
static mjtNum cb_gain(const mjModel* m, const mjData* d, int i) {
  (void)m, (void)i;
  seen(CB_GAIN, d);
  return 1;
}
static mjtNum cb_bias(const mjModel* m, const mjData* d, int i) {
  (void)m, (void)i;
  seen(CB_BIAS, d);
  return 0;
}
static mjtNum cb_dyn(const mjModel* m, const mjData* d, int i) {
  (void)m, (void)i;
  seen(CB_DYN, d);
  return 0;
}
static void cb_sensor(const mjModel* m, mjData* d, int stage) {
  (void)m, (void)stage;
  seen(CB_SENSOR, d);
}

#define STAGE(name, call)                              \
  do {                                                 \
    d->maxuse_stack = 0;                               \
    call;                                              \
    printf(" %s=%d", name, d->maxuse_stack);           \
    if (d->pstack) printf(" %s.pstack=%d", name, d->pstack); \
  } while (0)

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: stack MODEL [DISABLEFLAGS]\n");
    return 2;
  }
  char err[300];
  mjModel* m = mj_loadXML(argv[1], 0, err, sizeof err);
  if (!m) {
    printf("load-error\n");
    return 0;
  }
  if (argc > 2) m->opt.disableflags |= atoi(argv[2]);
  mju_user_error = on_error;
  mju_user_warning = on_warning;
  mjData* d = mj_makeData(m);

  // trajectory
  start(m, d);
  for (int k = 0; k < 20; k++) {
    drive(m, d);
    mj_step(m, d);
  }
  int peak20 = d->maxuse_stack;
  for (int k = 20; k < 200; k++) {
    drive(m, d);
    mj_step(m, d);
  }
  printf("steps=%d", d->maxuse_stack);

  // stages at the trajectory's end
  STAGE("forward", mj_forward(m, d));
  STAGE("fwdPosition", mj_fwdPosition(m, d));
  STAGE("collision", mj_collision(m, d));
  STAGE("makeConstraint", mj_makeConstraint(m, d));
  STAGE("transmission", mj_transmission(m, d));
  STAGE("projectConstraint", mj_projectConstraint(m, d));
  STAGE("fwdVelocity", mj_fwdVelocity(m, d));
  STAGE("sensorVel", mj_sensorVel(m, d));
  STAGE("fwdActuation", mj_fwdActuation(m, d));
  STAGE("fwdAcceleration", mj_fwdAcceleration(m, d));
  STAGE("fwdConstraint", mj_fwdConstraint(m, d));
  STAGE("inverse", mj_inverse(m, d));
  int solver = m->opt.solver, cone = m->opt.cone;
  for (int s = 0; s < 3; s++) {
    for (int c = 0; c < 2; c++) {
      char name[32];
      m->opt.solver = s;
      m->opt.cone = c;
      mj_forward(m, d);
      snprintf(name, sizeof name, "solver%d.cone%d", s, c);
      STAGE(name, mj_forward(m, d));
      m->opt.noslip_iterations = 3;
      snprintf(name, sizeof name, "noslip.solver%d.cone%d", s, c);
      STAGE(name, mj_forward(m, d));
      m->opt.noslip_iterations = 0;
    }
  }
  m->opt.solver = solver;
  m->opt.cone = cone;
  mj_forward(m, d);

  // functions with their own scratch
  int nv = m->nv, body = m->nbody > 1 ? 1 : 0;
  mjtNum* a = (mjtNum*)calloc(6 * nv + 1, sizeof(mjtNum));
  mjtNum* b = (mjtNum*)calloc(6 * nv + 1, sizeof(mjtNum));
  mjtNum point[3] = {0.1, 0.2, 0.3}, axis[3] = {0, 0, 1}, force[3] = {1, 2, 3};
  STAGE("jacSubtreeCom", mj_jacSubtreeCom(m, d, a, body));
  STAGE("jacPointAxis", mj_jacPointAxis(m, d, a, b, point, axis, body));
  STAGE("jacPointAxis.axis", mj_jacPointAxis(m, d, NULL, b, point, axis, body));
  STAGE("applyFT", mj_applyFT(m, d, force, point, point, body, a));
  STAGE("subtreeVel", mj_subtreeVel(m, d));
  STAGE("energyVel", mj_energyVel(m, d));
  STAGE("step1", mj_step1(m, d));
  STAGE("step2", mj_step2(m, d));
  int enable = m->opt.enableflags;
  m->opt.enableflags |= mjENBL_FWDINV;
  STAGE("step.fwdinv", mj_step(m, d));
  m->opt.enableflags = enable;
  int integrator = m->opt.integrator;
  for (int i = 0; i < 3; i++) {
    char name[32];
    m->opt.integrator = i;
    snprintf(name, sizeof name, "step.integrator%d", i);
    STAGE(name, mj_step(m, d));
  }
  m->opt.integrator = integrator;
  if (nv < 60) {
    int nx = 2 * nv + m->na, nu = m->nu, ns = m->nsensordata;
    mjtNum* A = (mjtNum*)calloc(nx * nx + 1, sizeof(mjtNum));
    mjtNum* B = (mjtNum*)calloc(nx * nu + 1, sizeof(mjtNum));
    mjtNum* C = (mjtNum*)calloc(ns * nx + 1, sizeof(mjtNum));
    mjtNum* D = (mjtNum*)calloc(ns * nu + 1, sizeof(mjtNum));
    STAGE("transitionFD", mjd_transitionFD(m, d, 1e-6, 1, A, B, C, D));
    STAGE("transitionFD.A", mjd_transitionFD(m, d, 1e-6, 0, A, NULL, NULL, NULL));
    free(A);
    free(B);
    free(C);
    free(D);
  }
  STAGE("printData", mj_printData(m, d, "/dev/null"));
  STAGE("setConst", mj_setConst(m, d));
  free(a);
  free(b);

  // the stack top in the callbacks, over one mj_forward and one mj_step
  mjcb_control = cb_control;
  mjcb_passive = cb_passive;
  mjcb_contactfilter = cb_filter;
  mjcb_act_gain = cb_gain;
  mjcb_act_bias = cb_bias;
  mjcb_act_dyn = cb_dyn;
  mjcb_sensor = cb_sensor;
  mj_forward(m, d);
  mj_step(m, d);
  mjcb_control = mjcb_passive = NULL;
  mjcb_contactfilter = NULL;
  mjcb_act_gain = mjcb_act_bias = mjcb_act_dyn = NULL;
  mjcb_sensor = NULL;
  for (int i = 0; i < NCB; i++) {
    if (cb_count[i]) {
      printf(" cb.%s=%ld/%ld/%d", cb_name[i], cb_count[i], cb_sum[i], cb_max[i]);
    }
  }

  // overflow point
  printf(" overflow: nstack=%d", peak20);
  printf(" runs=%d", steps_with_stack(m, peak20));
  printf(" nstack-1");
  printf(" runs=%d\n", steps_with_stack(m, peak20 - 1));
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
