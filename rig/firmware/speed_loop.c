#include "speed_loop.h"

#include <math.h>

/* Estimating over 16 counts keeps an encoder's uneven edges (its channels' phase and duty errors)
 * under a few per cent of the speed; at the slowest speeds that would take too long (79 ms at
 * 17 mm/s, a lag the loop cannot live with), so 10 ms and a whole quadrature cycle (4 counts, over
 * which those errors cancel) also do; never more than 50 ms. */
#define SPEED_MIN_COUNTS 16
#define SPEED_CYCLE_COUNTS 4
#define SPEED_ENOUGH_SPAN_US 10000u
#define SPEED_MAX_SPAN_MS 50u
#define SPEED_MAX_SPAN_US 50000u

float speed_estimate(struct speed_estimator *e, int32_t count, uint32_t last_edge_us, uint32_t now_us) {
  e->head = e->head + 1u == SPEED_HISTORY ? 0 : (uint8_t)(e->head + 1u);
  e->count[e->head] = count;
  e->edge_us[e->head] = last_edge_us;
  if (e->filled < SPEED_HISTORY) ++e->filled;

  /* No edge for 50 ms: slower than a count in 50 ms (1.7 mm/s on the reference disc), which reads
   * as standing still, with no need to search the history every millisecond at rest. */
  if (now_us - last_edge_us > SPEED_MAX_SPAN_US && (int32_t)(now_us - last_edge_us) > 0) return 0.0f;

  int32_t dc = 0;
  uint32_t dt = 0;
  uint8_t i = e->head;
  for (uint8_t k = 1; k < e->filled && k <= SPEED_MAX_SPAN_MS; ++k) {
    i = i == 0 ? SPEED_HISTORY - 1u : (uint8_t)(i - 1u); /* no division: the AVR has none */
    /* An edge from before a standstill belongs to no part of this motion: starting from rest,
     * counts over the time since it would read a fraction of the speed. */
    const uint32_t span = last_edge_us - e->edge_us[i];
    if (span > SPEED_MAX_SPAN_US) break;
    dc = count - e->count[i];
    dt = span;
    const int32_t magnitude = dc < 0 ? -dc : dc;
    if (magnitude >= SPEED_MIN_COUNTS || (magnitude >= SPEED_CYCLE_COUNTS && dt >= SPEED_ENOUGH_SPAN_US)) break;
  }
  if (dc == 0 || dt == 0) return 0.0f;
  float rate = (float)dc * 1e6f / (float)dt;
  /* No edge for longer than two counts take at this rate: the turntable has slowed since, to at
   * most two counts over that time. (One count's time is no sign: an encoder's edges are unevenly
   * spaced, and a deceleration makes the next one late by a little.) An edge may land between the
   * caller's reading of the clock and of the encoder, leaving the last edge after `now`: that is
   * no quiet at all, not four thousand seconds of it. */
  const int32_t quiet = (int32_t)(now_us - last_edge_us);
  if (quiet > 0 && fabsf(rate) * (float)quiet > 2e6f) {
    const float bound = 2e6f / (float)quiet; /* divided only when it bounds: the AVR divides slowly */
    rate = rate > 0 ? bound : -bound;
  }
  return rate;
}

void speed_controller_init(struct speed_controller *c) {
  /* The reference gearmotor turns the 60 mm track at 942 mm/s with no load at 12 V. The offset
   * overcomes its gearbox (0.2 A, a duty of 0.036 across its 2.2 ohm) and the contact's friction
   * at the paper's 2.2 N and a mu near 0.3 (0.08 A more), so that the integral trims only what
   * differs. Its mechanical time constant with the disc is about 55 ms and the PI's zero sits on
   * that pole, putting the closed loop's bandwidth near 45 rad/s: higher, the slowest speed
   * overshoots, as the first edges of a start from rest come 15 ms apart (measured on the
   * simulated board, tests/rig/usb/board_speed_loop_test.cpp). */
  c->kff = 1.0f / 942.0f;
  c->offset = 0.051f;
  c->kp = 0.0025f;
  c->ki = 0.045f;
  c->kacc = 0.055f / 942.0f;
  c->integral = 0.0f;
  c->last_target = 0.0f;
  c->step_hold_s = 0.0f;
}

/* Beyond this a target's change is a step, which the loop takes as fast as the motor can, within
 * about a tenth of a second. */
#define SPEED_RAMP_MAX_MM_S2 2000.0f
#define SPEED_STEP_HOLD_S 0.05f

float speed_controller_step(struct speed_controller *c, float target, float measured, float dt_s) {
  if (target <= 0.0f) {
    c->integral = 0.0f;
    c->last_target = 0.0f;
    return 0.0f;
  }
  const float error = target - measured;
  float base = c->kff * target + c->offset + c->kp * error;
  /* Following a profile's ramp takes the torque that accelerates the disc; left to the integral,
   * it stays there as a surplus where the ramp ends, and the speed overshoots the hold after it. */
  const float change = target - c->last_target;
  c->last_target = target;
  if (change != 0.0f && fabsf(change) <= SPEED_RAMP_MAX_MM_S2 * dt_s) base += c->kacc * change / dt_s;
  /* The feed-forward carries a step; for a while after one the integral only trims what it misses
   * near the target. Fed the whole step's error on the way up, it would hold that area as a surplus
   * and overshoot. After that while it integrates everything, so that a load the feed-forward does
   * not know, which leaves the speed far short, is made up. */
  if (change != 0.0f && fabsf(change) > SPEED_RAMP_MAX_MM_S2 * dt_s) c->step_hold_s = SPEED_STEP_HOLD_S;
  const float band = target * 0.2f > 5.0f ? target * 0.2f : 5.0f;
  const int hold = c->step_hold_s > 0.0f;
  if (hold) c->step_hold_s -= dt_s;
  float integral = c->integral + (!hold || fabsf(error) <= band ? c->ki * error * dt_s : 0.0f);
  float duty = base + integral;
  /* Integrate only while the output is not pinned: no wind-up during a step or a stall. */
  if (duty > 1.0f) {
    duty = 1.0f;
    if (integral > c->integral) integral = c->integral;
  } else if (duty < 0.0f) {
    duty = 0.0f;
    if (integral < c->integral) integral = c->integral;
  }
  c->integral = integral;
  return duty;
}

/* The reference gearmotor's stall current at full duty (12 V across 2.2 ohm); a held rotor draws
 * that times the duty, and 70 % of it still means no back-EMF worth the name (the winding warms, the
 * supply sags). Below a duty of 0.05 the motor is not driven at all. */
#define MOTOR_STALL_A 5.5f
#define MOTOR_HELD_FRACTION 0.7f
#define MOTOR_DRIVEN_DUTY 0.05f

enum motor_verdict motor_guard_check(struct motor_guard *g, float duty, float target, float measured, float current_A,
                                     int driver_fault, uint16_t edges, uint16_t glitches) {
  if (driver_fault) return MOTOR_DRIVER_FAULT;
  if (glitches > 0) return MOTOR_ENCODER_FAULT;
  /* Above 2 A for 100 ms: beyond what the turntable ever needs, and the driver's continuous rating. */
  g->overcurrent_ms = current_A > 2.0f ? (uint16_t)(g->overcurrent_ms + 1u) : 0u;
  if (g->overcurrent_ms >= 100u) return MOTOR_OVERCURRENT;
  /* Driven, yet no edge and no speed: either the disc is held, or it turns and the encoder is not
   * heard. The current tells them apart at any duty: a held rotor has no back-EMF and draws what
   * the duty drives through the winding alone; a turning one draws far less. Full drive is no
   * sign of either: at the slowest speeds the duty is a tenth. */
  const int driven = target > 0.0f && duty >= MOTOR_DRIVEN_DUTY && edges == 0 && measured < 0.1f * target;
  const int held = current_A >= MOTOR_HELD_FRACTION * MOTOR_STALL_A * duty;
  g->stall_ms = driven && held ? (uint16_t)(g->stall_ms + 1u) : 0u;
  g->silent_ms = driven && !held ? (uint16_t)(g->silent_ms + 1u) : 0u;
  if (g->stall_ms >= 500u) return MOTOR_STALL;
  if (g->silent_ms >= 300u) return MOTOR_ENCODER_FAULT;
  return MOTOR_OK;
}
