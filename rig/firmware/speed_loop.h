/* The turntable's closed speed loop: the encoder's speed from edge times, a PI controller with
 * feed-forward, and the guards that stop the motor (stall, over-current, encoder). Plain C, run
 * every millisecond; the same file runs on the chip and in the host's tests. */
#ifndef NIBRIG_SPEED_LOOP_H
#define NIBRIG_SPEED_LOOP_H

#include <stdint.h>

#define SPEED_HISTORY 51u /* the longest span, 50 ms, and now */

/* Speed from the encoder: counts over the time between their edges (not over a fixed window), so
 * a slow turntable with few edges a millisecond still reads precisely. */
struct speed_estimator {
  int32_t count[SPEED_HISTORY];
  uint32_t edge_us[SPEED_HISTORY];
  uint8_t head;
  uint8_t filled;
};

/* counts/s, given the encoder's count and the time of its last edge, now. */
float speed_estimate(struct speed_estimator *e, int32_t count, uint32_t last_edge_us, uint32_t now_us);

struct speed_controller {
  float kp;     /* duty per mm/s of error */
  float ki;     /* duty per mm of accumulated error */
  float kff;    /* duty per mm/s of target: the motor's no-load speed, inverted */
  float offset; /* duty that overcomes the gearbox's and the contact's friction */
  float kacc;   /* duty per mm/s^2 of a ramp: the motor's time constant over its no-load speed */
  float integral;
  float last_target;
  float step_hold_s; /* after a step, the integral trims only near the target for this long */
};

void speed_controller_init(struct speed_controller *c);
/* The PWM duty (0..1) toward `target` from `measured` (mm/s) after `dt_s`. */
float speed_controller_step(struct speed_controller *c, float target, float measured, float dt_s);

/* Above this the firmware never asks the bridge for more current at a start or a step: the
 * supply's 2 A with a margin, under the driver's current regulation (ITRIP, rig/HARDWARE.md). */
#define MOTOR_START_LIMIT_A 1.6f

/* Why the guard stops the motor: PROTOCOL.md's fault causes (rig_device.h numbers them). */
enum motor_verdict {
  MOTOR_OK = 0,
  MOTOR_STALL,
  MOTOR_OVERCURRENT,
  MOTOR_DRIVER_FAULT,
  MOTOR_SUPPLY_LOST,
  MOTOR_OVERSPEED,
  MOTOR_DISC_SLIPPING,
  MOTOR_ENCODER_SILENT,
  MOTOR_ENCODER_GLITCH,
  MOTOR_ENCODER_REVERSED,
  MOTOR_ENCODER_CHANNEL_LOST
};

/* One millisecond of the motor as the board saw it. */
struct motor_look {
  uint8_t ms;      /* since the last look */
  float duty;      /* asked of the bridge, 0..1 */
  float target;    /* mm/s; 0 while stopped */
  float measured;  /* mm/s from the encoder, signed: below 0 the disc turns backwards */
  float current_A; /* the driver's current mirror, mean over the millisecond */
  uint8_t driver_fault;
  int16_t counts;  /* encoder counts moved since the last look, signed */
  uint16_t edges_a, edges_b, glitches;
  float normal_N, tangential_N; /* the force channels' newest frame */
};

struct motor_guard {
  uint16_t stall_ms;
  uint16_t overcurrent_ms;
  uint16_t silent_ms;
  uint16_t supply_ms;
  uint16_t overspeed_ms;
  uint16_t slip_ms;
  int16_t backward_counts; /* moved against a forward drive, while the encoder reads backwards */
  uint16_t lone_edges[2];  /* edges of one encoder channel since the other's last */
};


enum motor_verdict motor_guard_check(struct motor_guard *g, const struct motor_look *m);

#endif
