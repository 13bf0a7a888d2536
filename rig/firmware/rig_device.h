/* The rig controller's protocol state (rig/PROTOCOL.md; its numbers in rig_protocol.h): requests,
 * mode, profile, calibration, refusals, the watchdog and the frames' values. Plain C with no hardware in it, so that the same
 * file runs on the ATmega32U4 and in the host's tests; the board supplies time, ADC means and the
 * encoder's speed, and persists what `rig_persist` holds. */
#ifndef NIBRIG_RIG_DEVICE_H
#define NIBRIG_RIG_DEVICE_H

#include <stdint.h>

#include "rig_protocol.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RIG_FIRMWARE_VERSION "1.2.0"
#define RIG_MAX_POINTS 64u
#define RIG_MAX_SPEED_MM_S 300.0f
#define RIG_MIN_RATE_HZ 1000u
/* At 4 kHz the chip has no cycle to spare: about 6 % of the frames were lost on the simulated board
 * (the frames' soft-float work, the endpoint's byte copies, the frame interrupt's 64-bit sums). */
#define RIG_MAX_RATE_HZ 3000u
#define RIG_WATCHDOG_MS 400u
#define RIG_ADC_FULL_COUNTS 1023.0f
/* SET_CALIBRATION's and SET_GEOMETRY's ranges (1.2) for this board's 10-bit converter and turntable.
 * A count at the tip (lever / counts per N) of at least 8.6 mN keeps twice the paper's 2.2 N load
 * within the ~511 counts either side of the zero; at most 0.11 N keeps a count within 5 % of that
 * load. Counts per turn within a factor of ten of the reference gearmotor's 4480; the track within
 * the 200 mm disc. */
#define RIG_MIN_N_PER_COUNT 0.0086f
#define RIG_MAX_N_PER_COUNT 0.11f
#define RIG_MIN_COUNTS_PER_REV 448.0f
#define RIG_MAX_COUNTS_PER_REV 44800.0f
#define RIG_MIN_RADIUS_MM 10.0f
#define RIG_MAX_RADIUS_MM 100.0f
/* The force channels stop the motor after this long unusable; a normal force below this is the tip
 * pulled up, or a bridge wired backwards. */
#define RIG_FORCE_BAD_MS 100u
#define RIG_NEGATIVE_NORMAL_N (-0.5f)

/* Packed as the AVR lays structs out anyway (it has no alignment), so that the host's tests read
 * the firmware's memory with these same definitions. */
#pragma pack(push, 1)

/* What the device keeps across power cycles (the board stores it in EEPROM). */
struct rig_persist {
  float counts_per_N[2]; /* normal, tangential */
  float lever;
  float zero_counts[2];
  float counts_per_rev;
  float radius_mm;
  char serial[RIG_SERIAL_BYTES];
};

struct rig_point {
  uint32_t t_ms;
  float mm_s;
};

/* The answer to one control request. */
struct rig_reply {
  uint8_t stall;     /* refused: STALL the pipe */
  uint8_t len;       /* IN: bytes in `data` */
  uint8_t data[64];
  uint8_t persist;   /* the persistent part changed: store it */
  uint8_t bootloader;/* after the status stage, detach and start the bootloader */
};

/* The ADC's means over one frame period, in counts (0..1023). */
struct rig_adc_means {
  float force_counts[2];
};

struct rig_frame {
  uint64_t t_us;
  uint32_t sequence;
  float speed_mm_s;
  float force_N[2];
  uint16_t flags;
};

struct rig {
  struct rig_persist persist;
  uint8_t streaming;
  uint8_t mode;
  uint8_t fault;
  uint8_t fault_cause;
  uint8_t reset_cause;
  uint8_t health;
  uint8_t force_bad;           /* the force channels unusable while the motor runs, since: */
  uint32_t force_bad_since_us;
  float force_N[2];     /* the newest frame's */
  uint8_t force_flags;  /* the newest frame's saturation flags */
  uint16_t sticky_flags; /* watchdog and fault flags until the next start */
  uint16_t frame_rate_hz;
  float target_mm_s;
  float speed_mm_s; /* the encoder's, as the board last measured */
  uint32_t sequence;
  uint32_t last_control_us;
  uint32_t profile_start_us;
  uint16_t profile_expected; /* points announced by PROFILE_BEGIN */
  uint16_t profile_received;
  uint16_t profile_held; /* a complete profile, or 0 */
  uint16_t profile_cursor;
  struct rig_point profile[RIG_MAX_POINTS];
  uint8_t refused_request;
  uint8_t refusal;
  /* ZERO_FORCE: the means of this many frames become the zero. */
  uint16_t zeroing_frames_left;
  uint16_t zeroing_frames;
  float zeroing_sum[2];
  uint8_t zero_taken; /* a new zero is in `persist`: store it */
  /* From `persist`, kept so that a frame costs no division (the AVR divides floats in software). */
  float newtons_per_count[2];
  float full_scale_N[2];
  float mm_per_count;
};

#pragma pack(pop)

/* Factory values: the reference design's parts (rig/HARDWARE.md). */
void rig_persist_defaults(struct rig_persist *p);
/* 0 when `p` holds values the device can use (finite, positive, a printable serial). */
int rig_persist_valid(const struct rig_persist *p);

void rig_init(struct rig *r, const struct rig_persist *p, uint32_t now_us);

/* One vendor control request: `setup` is the 8-byte setup packet, `data` an OUT request's data
 * stage (wLength bytes). An OUT request longer than 64 bytes never reaches here: the USB layer
 * refuses it with rig_refuse(). */
void rig_control(struct rig *r, const uint8_t setup[8], const uint8_t *data, uint32_t now_us,
                 struct rig_reply *reply);
void rig_refuse(struct rig *r, uint8_t request, enum rig_refusal why);

/* Every millisecond: the watchdog, the force channels, the profile's target, the mode. */
void rig_tick_ms(struct rig *r, uint32_t now_us);
/* A fault the board saw: the motor stops until the next start, and the status says why. */
void rig_fault(struct rig *r, enum rig_fault_cause cause);
/* The fault a cause belongs to. */
enum rig_fault rig_fault_of(enum rig_fault_cause cause);
/* The speed the loop is to reach now (0 when stopped). */
float rig_speed_target(const struct rig *r);

/* One frame from the frame period's ADC means; advances the sequence. Also feeds ZERO_FORCE. */
void rig_sample(struct rig *r, uint64_t t_us, const struct rig_adc_means *adc, struct rig_frame *f);
/* The frame's 28 bytes as PROTOCOL.md lays them out. */
void rig_frame_encode(const struct rig_frame *f, uint8_t out[RIG_FRAME_BYTES]);
/* The largest force either channel can report, N (for IDENTIFY and the saturation flag). */
float rig_force_full_scale(const struct rig *r, int channel);
/* Surface speed under the tip from encoder counts per second. */
float rig_speed_from_counts(const struct rig *r, float counts_per_s);

#ifdef __cplusplus
}
#endif

#endif
