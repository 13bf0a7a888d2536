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

enum motor_verdict { MOTOR_OK = 0, MOTOR_STALL, MOTOR_OVERCURRENT, MOTOR_DRIVER_FAULT, MOTOR_ENCODER_FAULT };

struct motor_guard {
  uint16_t stall_ms;
  uint16_t overcurrent_ms;
  uint16_t silent_ms;
};

/* One millisecond's look at the motor: the duty asked, the target and measured speed, the mean
 * motor current (A), whether the driver flags a fault, and encoder edges and glitches seen. */
enum motor_verdict motor_guard_check(struct motor_guard *g, float duty, float target, float measured, float current_A,
                                     int driver_fault, uint16_t edges, uint16_t glitches);

#endif
