// Long runs, built against each library (tests/long_run.rs):
//   longrun STEPS FILE...   per file, in a child process: load, then STEPS driven mj_step calls;
//   one line per file: "ok nan=<first step with a NaN or -1> warnings=<type:count,...>",
//   "load-error <message>", "error <mju_error message>", "crash <signal>" or "hang"
#define _DEFAULT_SOURCE
#include <math.h>
#include <mujoco/mujoco.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

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

static void run(const char* file, int steps) {
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
  int nan_at = -1;
  for (int s = 0; s < steps; s++) {
    for (int i = 0; i < m->nu; i++) {
      mjtNum x = sin(0.01 * s * (1 + 0.3 * i) + i);
      if (m->actuator_ctrllimited[i]) {
        mjtNum lo = m->actuator_ctrlrange[2 * i], hi = m->actuator_ctrlrange[2 * i + 1];
        d->ctrl[i] = lo + (hi - lo) * (0.5 + 0.45 * x);
      } else {
        d->ctrl[i] = x;
      }
    }
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
  int steps = atoi(argv[1]);
  for (int i = 2; i < argc; i++) {
    int fd[2];
    if (pipe(fd)) return 1;
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
      close(fd[0]);
      dup2(fd[1], 1);
      mju_user_error = on_error;
      mju_user_warning = quiet;
      run(argv[i], steps);
      fflush(stdout);
      _exit(0);
    }
    close(fd[1]);
    int ws = 0, done = 0;
    for (int t = 0; t < 12000 && !done; t++) {
      if (waitpid(pid, &ws, WNOHANG) == pid) done = 1;
      else usleep(10000);
    }
    char buf[1200];
    size_t n = 0;
    ssize_t r;
    if (!done) {
      kill(pid, SIGKILL);
      waitpid(pid, &ws, 0);
      printf("hang\n");
      close(fd[0]);
      continue;
    }
    while (n + 1 < sizeof buf && (r = read(fd[0], buf + n, sizeof buf - 1 - n)) > 0) n += r;
    buf[n] = 0;
    close(fd[0]);
    if (WIFSIGNALED(ws)) printf("crash %d\n", WTERMSIG(ws));
    else if (n == 0) printf("crash exit %d\n", WEXITSTATUS(ws));
    else fputs(buf, stdout);
    fflush(stdout);
  }
  return 0;
}
