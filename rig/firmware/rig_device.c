#include "rig_device.h"

#include <math.h>
#include <string.h>

/* Little-endian wire helpers: PROTOCOL.md is little-endian, and so are the AVR and x86, but the
 * host build must not depend on that. */
static void put_u16(uint8_t *p, uint16_t v) {
  p[0] = (uint8_t)v;
  p[1] = (uint8_t)(v >> 8);
}
static void put_u32(uint8_t *p, uint32_t v) {
  put_u16(p, (uint16_t)v);
  put_u16(p + 2, (uint16_t)(v >> 16));
}
static void put_f32(uint8_t *p, float v) {
  uint32_t bits;
  memcpy(&bits, &v, sizeof bits);
  put_u32(p, bits);
}
static uint16_t get_u16(const uint8_t *p) { return (uint16_t)(p[0] | (p[1] << 8)); }
static uint32_t get_u32(const uint8_t *p) { return (uint32_t)get_u16(p) | ((uint32_t)get_u16(p + 2) << 16); }
static float get_f32(const uint8_t *p) {
  uint32_t bits = get_u32(p);
  float v;
  memcpy(&v, &bits, sizeof v);
  return v;
}

static int positive_finite(float v) { return isfinite(v) && v > 0.0f; }
static int within(float v, float low, float high) { return isfinite(v) && v >= low && v <= high; }
/* A count's newtons at the tip within the board's range (rig_device.h): nothing else makes sense of
 * a 10-bit reading of the paper's load. */
static int tip_count_within(float counts_per_N, float lever) {
  return positive_finite(counts_per_N) && positive_finite(lever) &&
         within(lever / counts_per_N, RIG_MIN_N_PER_COUNT, RIG_MAX_N_PER_COUNT);
}

void rig_persist_defaults(struct rig_persist *p) {
  /* A 1 kg, 1 mV/V load cell at 5 V through a gain of 500 into the 10-bit ADC at 5 V: 0.255 V/N,
   * 52.2 counts/N; the amplifier's output sits at 1.0 V (204.6 counts) with no force. */
  p->counts_per_N[0] = p->counts_per_N[1] = 52.2f;
  p->lever = 1.0f;
  p->zero_counts[0] = p->zero_counts[1] = 511.5f;
  /* Pololu 37D 70:1 with its 64-count encoder: 4480 counts a turn; the tip 60 mm from the axis. */
  p->counts_per_rev = 4480.0f;
  p->radius_mm = 60.0f;
  memset(p->serial, 0, sizeof p->serial);
  memcpy(p->serial, "NIB-0000", 8);
}

static int serial_valid(const char *s) {
  unsigned i = 0;
  while (i < RIG_SERIAL_BYTES && s[i] != 0) {
    if (s[i] < 0x21 || s[i] > 0x7E) return 0;
    ++i;
  }
  if (i == 0) return 0;
  for (; i < RIG_SERIAL_BYTES; ++i) {
    if (s[i] != 0) return 0; /* padding is NUL to the end */
  }
  return 1;
}

int rig_persist_valid(const struct rig_persist *p) {
  return positive_finite(p->counts_per_N[0]) && positive_finite(p->counts_per_N[1]) &&
         positive_finite(p->lever) && isfinite(p->zero_counts[0]) && isfinite(p->zero_counts[1]) &&
         positive_finite(p->counts_per_rev) && positive_finite(p->radius_mm) && serial_valid(p->serial);
}

/* The conversions a frame needs, from what `persist` holds now. */
static void refresh_scales(struct rig *r) {
  for (int c = 0; c < 2; ++c) {
    r->newtons_per_count[c] = r->persist.lever / r->persist.counts_per_N[c];
    r->full_scale_N[c] = (RIG_ADC_FULL_COUNTS - r->persist.zero_counts[c]) * r->newtons_per_count[c];
  }
  r->mm_per_count = 6.2831853f * r->persist.radius_mm / r->persist.counts_per_rev;
}

void rig_init(struct rig *r, const struct rig_persist *p, uint32_t now_us) {
  memset(r, 0, sizeof *r);
  r->persist = *p;
  refresh_scales(r);
  r->frame_rate_hz = RIG_MIN_RATE_HZ;
  r->last_control_us = now_us;
}

float rig_force_full_scale(const struct rig *r, int channel) { return r->full_scale_N[channel]; }

float rig_speed_from_counts(const struct rig *r, float counts_per_s) { return counts_per_s * r->mm_per_count; }

void rig_refuse(struct rig *r, uint8_t request, enum rig_refusal why) {
  r->refused_request = request;
  r->refusal = (uint8_t)why;
}

static void stop_motor(struct rig *r) {
  r->mode = RIG_IDLE;
  r->target_mm_s = 0.0f;
}

/* A start clears the faults that stopped the motor: the host has seen them in the status. */
static void start(struct rig *r, uint8_t mode) {
  r->mode = mode;
  r->fault = RIG_FAULT_NONE;
  r->fault_cause = RIG_CAUSE_NONE;
  r->sticky_flags = 0;
}

static void identify(const struct rig *r, struct rig_reply *reply) {
  uint8_t *d = reply->data;
  memset(d, 0, RIG_IDENTITY_BYTES);
  put_u16(d + 0, RIG_PROTOCOL_VERSION);
  put_u16(d + 2, RIG_MAX_POINTS);
  put_f32(d + 4, RIG_MAX_SPEED_MM_S);
  const float fs0 = rig_force_full_scale(r, 0), fs1 = rig_force_full_scale(r, 1);
  put_f32(d + 8, fs0 < fs1 ? fs0 : fs1);
  put_u16(d + 12, r->frame_rate_hz);
  put_u16(d + 14, RIG_MIN_RATE_HZ);
  put_u16(d + 16, RIG_MAX_RATE_HZ);
  put_u16(d + 18, RIG_WATCHDOG_MS);
  memcpy(d + 20, r->persist.serial, RIG_SERIAL_BYTES);
  memcpy(d + 36, RIG_FIRMWARE_VERSION, sizeof RIG_FIRMWARE_VERSION - 1);
  reply->len = RIG_IDENTITY_BYTES;
}

static uint16_t current_flags(const struct rig *r) {
  uint16_t flags = r->sticky_flags;
  if (r->mode == RIG_SPEED || r->mode == RIG_PROFILE) flags |= RIG_PROFILE_RUNNING;
  return flags;
}

/* 16 bytes in 1.0 and 1.1; 1.2 appends why the motor stopped, what restarted the controller, and
 * its health. A host that asks for 16 reads the 1.1 layout. */
static void status(const struct rig *r, struct rig_reply *reply) {
  uint8_t *d = reply->data;
  put_u16(d + 0, current_flags(r));
  d[2] = r->mode;
  d[3] = r->fault;
  put_u32(d + 4, r->sequence);
  put_f32(d + 8, r->target_mm_s);
  put_u16(d + 12, r->profile_held);
  d[14] = r->refused_request;
  d[15] = r->refusal;
  d[16] = r->fault_cause;
  d[17] = r->reset_cause;
  d[18] = r->health;
  d[19] = 0;
  reply->len = RIG_STATUS_BYTES;
}

/* PROFILE_END's checks: starts at 0, never goes back in time, speeds within the motor's range. */
static int profile_valid(const struct rig *r) {
  if (r->profile[0].t_ms != 0) return 0;
  for (uint16_t i = 0; i < r->profile_received; ++i) {
    const float v = r->profile[i].mm_s;
    if (!isfinite(v) || v < 0.0f || v > RIG_MAX_SPEED_MM_S) return 0;
    if (i > 0 && r->profile[i].t_ms < r->profile[i - 1].t_ms) return 0;
  }
  return 1;
}

/* The expected wLength of each request: -1 any (IN, at least `min_in`), else exact. */
struct shape {
  uint8_t in;
  uint8_t len; /* IN: the least wLength; OUT: the exact one */
};

static int shape_of(uint8_t request, struct shape *s) {
  switch (request) {
    case RIG_IDENTIFY: *s = (struct shape){1, RIG_IDENTITY_BYTES}; return 1;
    case RIG_GET_STATUS: *s = (struct shape){1, RIG_STATUS_BYTES_1_0}; return 1;
    case RIG_GET_CALIBRATION: *s = (struct shape){1, RIG_CALIBRATION_BYTES}; return 1;
    case RIG_GET_GEOMETRY: *s = (struct shape){1, RIG_GEOMETRY_BYTES}; return 1;
    case RIG_PROFILE_READ: *s = (struct shape){1, 0}; return 1; /* 8·n, checked below */
    case RIG_SET_SPEED: *s = (struct shape){0, RIG_SPEED_BYTES}; return 1;
    case RIG_SET_CALIBRATION: *s = (struct shape){0, RIG_CALIBRATION_BYTES}; return 1;
    case RIG_SET_GEOMETRY: *s = (struct shape){0, RIG_GEOMETRY_BYTES}; return 1;
    case RIG_SET_SERIAL: *s = (struct shape){0, RIG_SERIAL_BYTES}; return 1;
    case RIG_PROFILE_WRITE: *s = (struct shape){0, 0}; return 1; /* 8·n, checked below */
    case RIG_SET_STREAMING:
    case RIG_START_PROFILE:
    case RIG_STOP:
    case RIG_PROFILE_BEGIN:
    case RIG_PROFILE_END:
    case RIG_ZERO_FORCE:
    case RIG_SET_FRAME_RATE:
    case RIG_ENTER_BOOTLOADER: *s = (struct shape){0, 0}; return 1;
    default: return 0;
  }
}

static int points_length_ok(uint16_t length) {
  return length >= RIG_POINT_BYTES && length <= RIG_MAX_POINTS_PER_REQUEST * RIG_POINT_BYTES &&
         length % RIG_POINT_BYTES == 0;
}

static void refuse(struct rig *r, uint8_t request, enum rig_refusal why, struct rig_reply *reply) {
  rig_refuse(r, request, why);
  reply->stall = 1;
  reply->len = 0;
}

void rig_control(struct rig *r, const uint8_t setup[8], const uint8_t *data, uint32_t now_us,
                 struct rig_reply *reply) {
  const uint8_t type = setup[0], request = setup[1];
  const uint16_t value = get_u16(setup + 2), index = get_u16(setup + 4), length = get_u16(setup + 6);
  memset(reply, 0, sizeof *reply);
  r->last_control_us = now_us; /* any request keeps the watchdog off */

  struct shape s;
  if (!shape_of(request, &s) || type != (s.in ? RIG_REQUEST_TYPE_IN : RIG_REQUEST_TYPE_OUT)) {
    refuse(r, request, RIG_REFUSE_UNKNOWN, reply);
    return;
  }
  const int points = request == RIG_PROFILE_READ || request == RIG_PROFILE_WRITE;
  if (points ? !points_length_ok(length) : (s.in ? length < s.len : length != s.len)) {
    refuse(r, request, RIG_REFUSE_LENGTH, reply);
    return;
  }
  const int uses_value = request == RIG_SET_STREAMING || request == RIG_PROFILE_BEGIN ||
                         request == RIG_SET_FRAME_RATE || request == RIG_ENTER_BOOTLOADER;
  const int uses_index = points;
  if ((!uses_value && value != 0) || (!uses_index && index != 0)) {
    refuse(r, request, RIG_REFUSE_RANGE, reply);
    return;
  }

  switch (request) {
    case RIG_IDENTIFY: identify(r, reply); return;
    case RIG_GET_STATUS: status(r, reply); return;
    case RIG_SET_STREAMING:
      if (value > 1) break;
      r->streaming = (uint8_t)value;
      return;
    case RIG_SET_SPEED: {
      const float v = get_f32(data);
      if (!isfinite(v) || v < 0.0f || v > RIG_MAX_SPEED_MM_S) break;
      r->target_mm_s = v;
      start(r, RIG_SPEED);
      return;
    }
    case RIG_START_PROFILE:
      if (r->profile_held == 0) {
        refuse(r, request, RIG_REFUSE_ORDER, reply);
        return;
      }
      r->profile_start_us = now_us;
      r->profile_cursor = 0;
      r->target_mm_s = r->profile[0].mm_s;
      start(r, RIG_PROFILE);
      return;
    case RIG_STOP: stop_motor(r); return;
    case RIG_PROFILE_BEGIN:
      if (value < 1 || value > RIG_MAX_POINTS) break;
      if (r->mode == RIG_PROFILE || r->mode == RIG_PROFILE_DONE) stop_motor(r);
      r->profile_expected = value;
      r->profile_received = 0;
      r->profile_held = 0;
      return;
    case RIG_PROFILE_WRITE: {
      const uint16_t n = length / RIG_POINT_BYTES;
      if (r->profile_expected == 0 || index != r->profile_received) {
        refuse(r, request, RIG_REFUSE_ORDER, reply);
        return;
      }
      if (index + n > r->profile_expected) break;
      for (uint16_t i = 0; i < n; ++i) {
        r->profile[index + i].t_ms = get_u32(data + RIG_POINT_BYTES * i);
        r->profile[index + i].mm_s = get_f32(data + RIG_POINT_BYTES * i + 4);
      }
      r->profile_received += n;
      return;
    }
    case RIG_PROFILE_END:
      if (r->profile_expected == 0 || r->profile_received != r->profile_expected) {
        refuse(r, request, RIG_REFUSE_ORDER, reply);
        return;
      }
      if (!profile_valid(r)) break;
      r->profile_held = r->profile_received;
      r->profile_expected = 0;
      return;
    case RIG_PROFILE_READ: {
      const uint16_t n = length / RIG_POINT_BYTES;
      if (index + n > r->profile_held) break;
      for (uint16_t i = 0; i < n; ++i) {
        put_u32(reply->data + RIG_POINT_BYTES * i, r->profile[index + i].t_ms);
        put_f32(reply->data + RIG_POINT_BYTES * i + 4, r->profile[index + i].mm_s);
      }
      reply->len = (uint8_t)length;
      return;
    }
    case RIG_ZERO_FORCE: {
      /* 100 ms of frames, whatever the rate. */
      r->zeroing_frames = (uint16_t)(r->frame_rate_hz / 10u);
      r->zeroing_frames_left = r->zeroing_frames;
      r->zeroing_sum[0] = r->zeroing_sum[1] = 0.0f;
      return;
    }
    case RIG_SET_FRAME_RATE:
      if (value < RIG_MIN_RATE_HZ || value > RIG_MAX_RATE_HZ) break;
      r->frame_rate_hz = value;
      return;
    case RIG_GET_CALIBRATION:
      put_f32(reply->data + 0, r->persist.counts_per_N[0]);
      put_f32(reply->data + 4, r->persist.counts_per_N[1]);
      put_f32(reply->data + 8, r->persist.lever);
      reply->len = 12;
      return;
    case RIG_SET_CALIBRATION: {
      const float n = get_f32(data), t = get_f32(data + 4), lever = get_f32(data + 8);
      if (!tip_count_within(n, lever) || !tip_count_within(t, lever)) break;
      r->persist.counts_per_N[0] = n;
      r->persist.counts_per_N[1] = t;
      r->persist.lever = lever;
      refresh_scales(r);
      reply->persist = 1;
      return;
    }
    case RIG_GET_GEOMETRY:
      put_f32(reply->data + 0, r->persist.counts_per_rev);
      put_f32(reply->data + 4, r->persist.radius_mm);
      reply->len = 8;
      return;
    case RIG_SET_GEOMETRY: {
      const float counts = get_f32(data), radius = get_f32(data + 4);
      if (!within(counts, RIG_MIN_COUNTS_PER_REV, RIG_MAX_COUNTS_PER_REV) ||
          !within(radius, RIG_MIN_RADIUS_MM, RIG_MAX_RADIUS_MM)) {
        break;
      }
      r->persist.counts_per_rev = counts;
      r->persist.radius_mm = radius;
      refresh_scales(r);
      reply->persist = 1;
      return;
    }
    case RIG_SET_SERIAL:
      if (!serial_valid((const char *)data)) break;
      memcpy(r->persist.serial, data, RIG_SERIAL_BYTES);
      reply->persist = 1;
      return;
    case RIG_ENTER_BOOTLOADER:
      if (value != RIG_BOOTLOADER_KEY) break;
      if (rig_speed_target(r) > 0.0f) {
        refuse(r, request, RIG_REFUSE_ORDER, reply);
        return;
      }
      r->streaming = 0;
      reply->bootloader = 1;
      return;
  }
  refuse(r, request, RIG_REFUSE_RANGE, reply);
}

enum rig_fault rig_fault_of(enum rig_fault_cause cause) {
  if (cause == RIG_CAUSE_NONE) return RIG_FAULT_NONE;
  if (cause <= RIG_CAUSE_SLIP) return RIG_FAULT_MOTOR;
  if (cause <= RIG_CAUSE_ENCODER_CHANNEL) return RIG_FAULT_ENCODER;
  if (cause == RIG_CAUSE_HOST_SILENT) return RIG_FAULT_WATCHDOG;
  return RIG_FAULT_FORCE;
}

void rig_fault(struct rig *r, enum rig_fault_cause cause) {
  const enum rig_fault fault = rig_fault_of(cause);
  if (r->mode == RIG_IDLE && r->fault == fault) return;
  stop_motor(r);
  r->fault = (uint8_t)fault;
  r->fault_cause = (uint8_t)cause;
  r->sticky_flags |= fault == RIG_FAULT_MOTOR     ? RIG_MOTOR_FAULT
                     : fault == RIG_FAULT_ENCODER ? RIG_ENCODER_FAULT
                     : fault == RIG_FAULT_FORCE   ? RIG_FORCE_FAULT
                                                  : RIG_WATCHDOG_STOPPED;
}

/* The profile's speed at `t_ms`: straight lines between breakpoints; a step is two points at one
 * time. The cursor only moves forward, so each tick costs a comparison or two. */
static float profile_speed(struct rig *r, uint32_t t_ms) {
  const struct rig_point *p = r->profile;
  const uint16_t n = r->profile_held;
  while (r->profile_cursor + 1u < n && p[r->profile_cursor + 1].t_ms <= t_ms) ++r->profile_cursor;
  const uint16_t i = r->profile_cursor;
  if (i + 1u >= n) return p[n - 1].mm_s;
  const uint32_t span = p[i + 1].t_ms - p[i].t_ms;
  const float f = (float)(t_ms - p[i].t_ms) / (float)span;
  return p[i].mm_s + (p[i + 1].mm_s - p[i].mm_s) * f;
}

void rig_tick_ms(struct rig *r, uint32_t now_us) {
  /* Whatever drives the motor: a speed, a profile, or the last speed a finished profile holds. */
  const int running = rig_speed_target(r) > 0.0f;
  if (running && now_us - r->last_control_us > RIG_WATCHDOG_MS * 1000ul) {
    rig_fault(r, RIG_CAUSE_HOST_SILENT);
    return;
  }
  /* A channel at its end, or the tip pulled up by half a newton, for 100 ms while the disc turns:
   * a cell unplugged or overloaded (a hand on the holder), or its bridge wired backwards. The
   * frames would be no measurement, and a hand may be where the disc turns. */
  const int unusable = (r->force_flags & (RIG_NORMAL_SATURATED | RIG_TANGENTIAL_SATURATED)) != 0 ||
                       r->force_N[0] < RIG_NEGATIVE_NORMAL_N;
  if (!(running && unusable)) {
    r->force_bad = 0;
  } else if (!r->force_bad) {
    r->force_bad = 1;
    r->force_bad_since_us = now_us;
  }
  if (r->force_bad && now_us - r->force_bad_since_us >= RIG_FORCE_BAD_MS * 1000ul) {
    rig_fault(r, r->force_flags ? RIG_CAUSE_FORCE_SATURATED : RIG_CAUSE_FORCE_NEGATIVE);
    return;
  }
  if (r->mode == RIG_PROFILE) {
    const uint32_t t_ms = (now_us - r->profile_start_us) / 1000ul;
    r->target_mm_s = profile_speed(r, t_ms);
    if (t_ms >= r->profile[r->profile_held - 1].t_ms) r->mode = RIG_PROFILE_DONE;
  }
}

float rig_speed_target(const struct rig *r) { return r->mode == RIG_IDLE ? 0.0f : r->target_mm_s; }

void rig_sample(struct rig *r, uint64_t t_us, const struct rig_adc_means *adc, struct rig_frame *f) {
  f->t_us = t_us;
  f->sequence = r->sequence++;
  f->speed_mm_s = r->speed_mm_s;
  f->flags = current_flags(r);
  for (int c = 0; c < 2; ++c) {
    const float counts = adc->force_counts[c];
    const float force = (counts - r->persist.zero_counts[c]) * r->newtons_per_count[c];
    f->force_N[c] = force;
    r->force_N[c] = force;
    /* At either end of the converter, or beyond the full scale: the reading is not the force. */
    if (counts >= RIG_ADC_FULL_COUNTS - 1.0f || counts <= 1.0f || fabsf(force) >= r->full_scale_N[c]) {
      f->flags |= c == 0 ? RIG_NORMAL_SATURATED : RIG_TANGENTIAL_SATURATED;
    }
  }
  r->force_flags = (uint8_t)(f->flags & (RIG_NORMAL_SATURATED | RIG_TANGENTIAL_SATURATED));
  if (r->zeroing_frames_left > 0) {
    r->zeroing_sum[0] += adc->force_counts[0];
    r->zeroing_sum[1] += adc->force_counts[1];
    if (--r->zeroing_frames_left == 0) {
      r->persist.zero_counts[0] = r->zeroing_sum[0] / (float)r->zeroing_frames;
      r->persist.zero_counts[1] = r->zeroing_sum[1] / (float)r->zeroing_frames;
      r->zero_taken = 1;
      refresh_scales(r);
    }
  }
}

void rig_frame_encode(const struct rig_frame *f, uint8_t out[RIG_FRAME_BYTES]) {
  put_u32(out + 0, (uint32_t)f->t_us);
  put_u32(out + 4, (uint32_t)(f->t_us >> 32));
  put_u32(out + 8, f->sequence);
  put_f32(out + 12, f->speed_mm_s);
  put_f32(out + 16, f->force_N[0]);
  put_f32(out + 20, f->force_N[1]);
  put_u16(out + 24, f->flags);
  put_u16(out + 26, 0);
}
