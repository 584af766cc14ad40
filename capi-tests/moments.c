// The rows of actuator_moment after whatever else writes the array buffer (tests/moments.rs):
// resets (debug pattern too), copies into data in another state, the buffer copied by hand,
// actuators edited in mjModel to other joints and transmission types between calls, dense
// and sparse Jacobians. Prints hashes of the whole matrix and of the actuation it drives,
// identical on both libraries: ours zeroes of a joint's row only the columns the last call
// wrote.
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

static void show(const char* what, const mjModel* m, const mjData* d) {
  uint64_t h = 14695981039346656037ull;
  h = hash(h, d->actuator_moment, sizeof(mjtNum) * m->nu * m->nv);
  h = hash(h, d->actuator_length, sizeof(mjtNum) * m->nu);
  h = hash(h, d->actuator_velocity, sizeof(mjtNum) * m->nu);
  h = hash(h, d->qfrc_actuator, sizeof(mjtNum) * m->nv);
  h = hash(h, d->qacc, sizeof(mjtNum) * m->nv);
  int nonzero = 0;
  for (int i = 0; i < m->nu * m->nv; i++) nonzero += d->actuator_moment[i] != 0;
  printf("%-32s nonzero %3d hash %016llx\n", what, nonzero, (unsigned long long)h);
}

static void steps(const mjModel* m, mjData* d, int n, double phase) {
  for (int s = 0; s < n; s++) {
    for (int i = 0; i < m->nu; i++) d->ctrl[i] = 0.5 * sin(0.05 * s + i + phase);
    mj_step(m, d);
  }
}

int main(int argc, char** argv) {
  for (int a = 1; a < argc; a++) {
    char err[1000];
    mjModel* m = mj_loadXML(argv[a], NULL, err, sizeof err);
    if (!m) {
      printf("%s: %s\n", argv[a], err);
      return 1;
    }
    for (int sparse = 0; sparse < 2; sparse++) {
      m->opt.jacobian = sparse ? mjJAC_SPARSE : mjJAC_DENSE;
      printf("%s jacobian %s\n", m->names, sparse ? "sparse" : "dense");
      mjData* d = mj_makeData(m);
      mjData* d2 = mj_makeData(m);
      steps(m, d, 40, 0);
      show("stepped", m, d);
      mj_resetDataDebug(m, d, 0x5a);
      steps(m, d, 3, 0);
      show("debug reset, stepped", m, d);
      steps(m, d2, 70, 1);
      mj_copyData(d2, m, d);
      mj_forward(m, d2);
      show("copied into, forward", m, d2);
      steps(m, d2, 30, 2);
      memcpy(d2->buffer, d->buffer, d->nbuffer);
      mj_forward(m, d2);
      show("buffer copied, forward", m, d2);
      // the hinge's motor moved to the ball, the slide's to a tendon, a tendon's to the slide
      int hinge = mj_name2id(m, mjOBJ_ACTUATOR, "hinge");
      int slide = mj_name2id(m, mjOBJ_ACTUATOR, "slide");
      int wrap = mj_name2id(m, mjOBJ_ACTUATOR, "wrap");
      int saved[6] = {m->actuator_trnid[2 * hinge], m->actuator_trnid[2 * slide],
                      m->actuator_trnid[2 * wrap], m->actuator_trntype[hinge],
                      m->actuator_trntype[slide], m->actuator_trntype[wrap]};
      m->actuator_trnid[2 * hinge] = mj_name2id(m, mjOBJ_JOINT, "ball");
      m->actuator_trnid[2 * slide] = mj_name2id(m, mjOBJ_TENDON, "wrap");
      m->actuator_trntype[slide] = mjTRN_TENDON;
      m->actuator_trnid[2 * wrap] = mj_name2id(m, mjOBJ_JOINT, "slide");
      m->actuator_trntype[wrap] = mjTRN_JOINT;
      steps(m, d, 5, 3);
      show("edited, stepped", m, d);
      m->actuator_trnid[2 * hinge] = saved[0];
      m->actuator_trnid[2 * slide] = saved[1];
      m->actuator_trnid[2 * wrap] = saved[2];
      m->actuator_trntype[hinge] = saved[3];
      m->actuator_trntype[slide] = saved[4];
      m->actuator_trntype[wrap] = saved[5];
      steps(m, d, 5, 4);
      show("restored, stepped", m, d);
      mj_resetData(m, d);
      mj_forward(m, d);
      show("reset, forward", m, d);
      mj_deleteData(d2);
      mj_deleteData(d);
    }
    mj_deleteModel(m);
  }
  return 0;
}
