// Helpers of the loader, long-run and bench programs: a child process with a time limit, and
// deterministic controls.
#pragma once
#define _DEFAULT_SOURCE
#include <math.h>
#include <mujoco/mujoco.h>
#include <signal.h>
#include <stdio.h>
#include <sys/wait.h>
#include <unistd.h>

#include "wait_child.h"

// Runs fn(file) in a child process with its stdout captured and prints that output, or
// "crash <signal>", "crash exit <code>" (no output), or "hang" after `seconds`.
static inline void in_child(void (*fn)(const char*), const char* file, int seconds) {
  int fd[2];
  if (pipe(fd)) return;
  fflush(stdout);
  pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    dup2(fd[1], 1);
    fn(file);
    fflush(stdout);
    _exit(0);
  }
  close(fd[1]);
  int ws = 0;
  if (!wait_child(pid, seconds, &ws)) {
    printf("hang\n");
    close(fd[0]);
    return;
  }
  char buf[2000];
  size_t n = 0;
  ssize_t r;
  while (n + 1 < sizeof buf && (r = read(fd[0], buf + n, sizeof buf - 1 - n)) > 0) n += r;
  buf[n] = 0;
  close(fd[0]);
  if (WIFSIGNALED(ws)) printf("crash %d\n", WTERMSIG(ws));
  else if (n == 0) printf("crash exit %d\n", WEXITSTATUS(ws));
  else fputs(buf, stdout);
  fflush(stdout);
}

// Controls at step s: sinusoids, inside the control range of limited actuators.
static inline void drive_controls(const mjModel* m, mjData* d, int s) {
  for (int i = 0; i < m->nu; i++) {
    mjtNum x = sin(0.01 * s * (1 + 0.3 * i) + i);
    if (m->actuator_ctrllimited[i]) {
      mjtNum lo = m->actuator_ctrlrange[2 * i], hi = m->actuator_ctrlrange[2 * i + 1];
      d->ctrl[i] = lo + (hi - lo) * (0.5 + 0.45 * x);
    } else {
      d->ctrl[i] = x;
    }
  }
}
