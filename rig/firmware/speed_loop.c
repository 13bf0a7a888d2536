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

/* The reference gearmotor (rig/HARDWARE.md): 12 V across a 2.18 ohm winding (5.5 A stalled), and a
 * back-EMF of 0.736 V per rad/s at the disc, 0.0123 V per mm/s at the 60 mm track. In duty: what
 * drives a current through the winding at rest, and what the back-EMF of a mm/s takes. Folded into
 * constants: the AVR multiplies floats in software, and divides far slower. */
#define MOTOR_SUPPLY_V 12.0f
#define MOTOR_WINDING_OHM (12.0f / 5.5f)
#define MOTOR_BEMF_V_PER_MM_S (0.736f / 60.0f)
#define MOTOR_DUTY_PER_A (MOTOR_WINDING_OHM / MOTOR_SUPPLY_V)
#define MOTOR_DUTY_PER_MM_S (MOTOR_BEMF_V_PER_MM_S / MOTOR_SUPPLY_V)

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
  /* A start or a step asks at most MOTOR_START_LIMIT_A of the winding beyond the back-EMF of the
   * speed reached: a stalled rotor draws the supply over the winding, 5.5 A, beyond the driver's
   * regulation and the supply's rating. */
  float most = MOTOR_START_LIMIT_A * MOTOR_DUTY_PER_A + MOTOR_DUTY_PER_MM_S * fabsf(measured);
  if (most > 1.0f) most = 1.0f;
  /* Integrate only while the output is not pinned: no wind-up during a step or a stall. */
  if (duty > most) {
    duty = most;
    if (integral > c->integral) integral = c->integral;
    /* A step held to the current limit is still a step: the hold runs from where the limit lets go. */
    if (c->step_hold_s > 0.0f) c->step_hold_s = SPEED_STEP_HOLD_S;
  } else if (duty < 0.0f) {
    duty = 0.0f;
    if (integral < c->integral) integral = c->integral;
  }
  c->integral = integral;
  return duty;
}

/* The current (A) the reference motor draws at `duty` turning at `speed` mm/s: the supply across
 * the winding, less the back-EMF. */
static float motor_expected_current_A(float duty, float speed) {
  return (duty - MOTOR_DUTY_PER_MM_S * fabsf(speed)) * (1.0f / MOTOR_DUTY_PER_A);
}

/* A held rotor draws what the duty drives through the winding alone; 70 % of that still means no
 * back-EMF worth the name (the winding warms, the supply sags). Below a duty of 0.05 the motor is
 * not driven at all. */
#define MOTOR_STALL_A (MOTOR_SUPPLY_V / MOTOR_WINDING_OHM)
#define MOTOR_HELD_FRACTION 0.7f
#define MOTOR_DRIVEN_DUTY 0.05f
/* Above the firmware's own start limit and under the driver's 2.0 A regulation: something draws
 * current the firmware did not ask for (a binding gearbox, a winding shorting). */
#define MOTOR_OVERCURRENT_A 1.8f
#define MOTOR_OVERCURRENT_MS 100u
/* Driven to draw half an ampere or more, and the current mirror reads a tenth of it: the bridge
 * has no supply (the emergency stop, the fuse, the adapter unplugged). 20 ms rides out the
 * mirror's settling after a step. */
#define MOTOR_SUPPLY_EXPECTED_A 0.5f
#define MOTOR_SUPPLY_FRACTION 0.1f
#define MOTOR_SUPPLY_MS 20u
/* Faster than the protocol's highest target by a fifth, for 10 ms: the loop has lost the disc. */
#define MOTOR_OVERSPEED_MM_S (1.2f * 300.0f)
#define MOTOR_OVERSPEED_MS 10u
/* 16 counts (1.3 mm of track) backwards while driven forwards: no vibration moves the disc that far
 * against the drive; a reversed encoder does within a few milliseconds. */
#define MOTOR_BACKWARD_COUNTS 16
/* A quadrature encoder's channels alternate; eight edges of one with none of the other is a
 * channel whose wire is off (the count then only dithers, whatever the disc does). */
#define MOTOR_LONE_EDGES 8u
/* Turning at the target under a loaded tip (0.5 N or more) with no friction (under 0.03 N, a count
 * and a half) for half a second: the disc stands still while the motor turns, slipping on its
 * hub. The paper's least friction, 0.29 N, is ten times the bound. */
#define MOTOR_SLIP_NORMAL_N 0.5f
#define MOTOR_SLIP_TANGENTIAL_N 0.03f
#define MOTOR_SLIP_MS 500u

/* Milliseconds a condition has held: a late loop looks once for several. */
static uint16_t count_while(uint16_t held_ms, int condition, uint8_t ms) {
  return condition ? (uint16_t)(held_ms + ms) : 0u;
}

enum motor_verdict motor_guard_check(struct motor_guard *g, const struct motor_look *m) {
  const int driven = m->target > 0.0f;
  if (!driven) {
    /* Stopped: nothing to guard, and nothing carried into the next start. */
    const struct motor_guard idle = {0};
    *g = idle;
    return MOTOR_OK;
  }
  if (m->driver_fault) return MOTOR_DRIVER_FAULT;
  if (m->glitches > 0) return MOTOR_ENCODER_GLITCH;

  if (m->edges_b > 0) g->lone_edges[0] = 0;
  if (m->edges_a > 0) g->lone_edges[1] = 0;
  g->lone_edges[0] = (uint16_t)(g->lone_edges[0] + (m->edges_b == 0 ? m->edges_a : 0u));
  g->lone_edges[1] = (uint16_t)(g->lone_edges[1] + (m->edges_a == 0 ? m->edges_b : 0u));
  const int lone = g->lone_edges[0] >= MOTOR_LONE_EDGES || g->lone_edges[1] >= MOTOR_LONE_EDGES;

  /* The encoder says backwards while the drive is forwards: its channels, or the motor's leads,
   * are swapped. Whatever its edges look like, this is the runaway the loop would make of it. */
  g->backward_counts = m->measured < 0.0f ? (int16_t)(g->backward_counts + m->counts) : 0;
  if (g->backward_counts <= -MOTOR_BACKWARD_COUNTS) return MOTOR_ENCODER_REVERSED;
  g->overspeed_ms = count_while(g->overspeed_ms, fabsf(m->measured) > MOTOR_OVERSPEED_MM_S, m->ms);
  if (g->overspeed_ms >= MOTOR_OVERSPEED_MS) return MOTOR_OVERSPEED;

  g->overcurrent_ms = count_while(g->overcurrent_ms, m->current_A > MOTOR_OVERCURRENT_A, m->ms);
  if (g->overcurrent_ms >= MOTOR_OVERCURRENT_MS) return MOTOR_OVERCURRENT;
  /* A tenth of the current the duty drives through a winding at rest bounds a tenth of any current
   * it drives: the supply check's sum is made only below it. */
  const float held_A = MOTOR_HELD_FRACTION * MOTOR_STALL_A * m->duty;
  int unsupplied = 0;
  if (m->duty >= MOTOR_DRIVEN_DUTY && m->current_A < MOTOR_SUPPLY_FRACTION * MOTOR_STALL_A * m->duty) {
    const float expected = motor_expected_current_A(m->duty, m->measured);
    unsupplied = expected >= MOTOR_SUPPLY_EXPECTED_A && m->current_A < MOTOR_SUPPLY_FRACTION * expected;
  }
  g->supply_ms = count_while(g->supply_ms, unsupplied, m->ms);
  if (g->supply_ms >= MOTOR_SUPPLY_MS) return MOTOR_SUPPLY_LOST;

  /* Driven, yet the encoder reads no motion: either the disc is held, or it turns and the encoder
   * is not heard (whatever edges come: one channel alone only dithers the count). The current
   * tells them apart at any duty: a held rotor draws what the duty drives through the winding; a
   * turning one far less, but not nothing. Full drive is no sign of either: at the slowest speeds
   * the duty is a tenth. */
  const int still = m->duty >= MOTOR_DRIVEN_DUTY && fabsf(m->measured) < 0.1f * m->target;
  const int held = still && m->current_A >= held_A;
  g->stall_ms = count_while(g->stall_ms, held, m->ms);
  g->silent_ms = count_while(g->silent_ms, still && !held && m->current_A >= 0.05f, m->ms);
  if (g->stall_ms >= 500u) return MOTOR_STALL;
  if (g->silent_ms >= 300u) return lone ? MOTOR_ENCODER_CHANNEL_LOST : MOTOR_ENCODER_SILENT;

  /* Cheapest first: a tip that measures friction ends it at once. */
  g->slip_ms = count_while(g->slip_ms, fabsf(m->tangential_N) < MOTOR_SLIP_TANGENTIAL_N &&
                                           m->normal_N >= MOTOR_SLIP_NORMAL_N && m->target >= 10.0f &&
                                           fabsf(m->measured - m->target) < 0.2f * m->target, m->ms);
  if (g->slip_ms >= MOTOR_SLIP_MS) return MOTOR_DISC_SLIPPING;
  return MOTOR_OK;
}
