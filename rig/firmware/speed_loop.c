#include "speed_loop.h"

#include <math.h>

/* Estimating over at least this many counts keeps the quantisation under 1/16 of the speed; never
 * over more than 50 ms, so the loop still sees a change quickly at the slowest speed. */
#define SPEED_MIN_COUNTS 16
#define SPEED_MAX_SPAN_MS 50u

float speed_estimate(struct speed_estimator *e, int32_t count, uint32_t last_edge_us, uint32_t now_us) {
  e->head = e->head + 1u == SPEED_HISTORY ? 0 : (uint8_t)(e->head + 1u);
  e->count[e->head] = count;
  e->edge_us[e->head] = last_edge_us;
  if (e->filled < SPEED_HISTORY) ++e->filled;

  int32_t dc = 0;
  uint32_t dt = 0;
  uint8_t i = e->head;
  for (uint8_t k = 1; k < e->filled && k <= SPEED_MAX_SPAN_MS; ++k) {
    i = i == 0 ? SPEED_HISTORY - 1u : (uint8_t)(i - 1u); /* no division: the AVR has none */
    dc = count - e->count[i];
    dt = last_edge_us - e->edge_us[i];
    if (dc >= SPEED_MIN_COUNTS || dc <= -SPEED_MIN_COUNTS) break;
  }
  if (dc == 0 || dt == 0) return 0.0f;
  float rate = (float)dc * 1e6f / (float)dt;
  /* No edge for much longer than one count takes at this rate: the turntable has slowed since, and
   * the time since the last edge bounds its speed. "Much": quadrature edges are never evenly spaced
   * (an encoder's phase error, the edges' own timing), so one and a half periods. An edge stamped
   * after `now_us` was taken (the interrupt came in between) is no quiet at all. */
  const int32_t quiet = (int32_t)(now_us - last_edge_us);
  if (quiet > 0 && (float)quiet * fabsf(rate) > 1.5e6f) {
    const float bound = 1e6f / (float)quiet;
    rate = rate > 0 ? bound : -bound;
  }
  return rate;
}

void speed_controller_init(struct speed_controller *c) {
  /* The reference gearmotor turns the 60 mm track at 942 mm/s with no load at 12 V and needs
   * 0.2 A (a duty of 0.036 across its 2.2 ohm) to overcome its gearbox; its mechanical time
   * constant with the disc is about 55 ms. The PI's zero sits on that pole, putting the closed
   * loop's bandwidth near 70 rad/s (a rise time near 30 ms). */
  c->kff = 1.0f / 942.0f;
  c->offset = 0.036f;
  c->kp = 0.004f;
  c->ki = 0.07f;
  c->integral = 0.0f;
}

float speed_controller_step(struct speed_controller *c, float target, float measured, float dt_s) {
  if (target <= 0.0f) {
    c->integral = 0.0f;
    return 0.0f;
  }
  const float error = target - measured;
  const float base = c->kff * target + c->offset + c->kp * error;
  float integral = c->integral + c->ki * error * dt_s;
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

enum motor_verdict motor_guard_check(struct motor_guard *g, float duty, float target, float measured, float current_A,
                                     int driver_fault, uint16_t edges, uint16_t glitches) {
  if (driver_fault) return MOTOR_DRIVER_FAULT;
  if (glitches > 0) return MOTOR_ENCODER_FAULT;
  /* Full drive and almost no motion for half a second: blocked. */
  g->stall_ms = (duty >= 0.9f && measured < 0.1f * target) ? (uint16_t)(g->stall_ms + 1u) : 0u;
  if (g->stall_ms >= 500u) return MOTOR_STALL;
  /* Above 2 A for 100 ms: beyond what the turntable ever needs, and the driver's continuous rating. */
  g->overcurrent_ms = current_A > 2.0f ? (uint16_t)(g->overcurrent_ms + 1u) : 0u;
  if (g->overcurrent_ms >= 100u) return MOTOR_OVERCURRENT;
  /* Driven well above the friction and drawing current, but no edge for 300 ms: the encoder is lost. */
  g->silent_ms = (duty >= 0.3f && current_A > 0.3f && edges == 0) ? (uint16_t)(g->silent_ms + 1u) : 0u;
  if (g->silent_ms >= 300u) return MOTOR_ENCODER_FAULT;
  return MOTOR_OK;
}
