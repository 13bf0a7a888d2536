/* The rig controller's wire protocol (rig/PROTOCOL.md) in one place: the USB identity, the request
 * numbers, the replies' and frames' sizes, and the numbers the device reports (refusals, modes,
 * faults and their causes, reset causes, health and frame flags). Plain C, included by the firmware
 * (rig_device.h) and by the host's driver (rig/usb/usb_protocol.hpp), so the two cannot disagree. */
#ifndef NIBRIG_RIG_PROTOCOL_H
#define NIBRIG_RIG_PROTOCOL_H

#define RIG_USB_VENDOR_ID 0x1209u  /* pid.codes */
#define RIG_USB_PRODUCT_ID 0x000Au /* pid.codes' test range */
#define RIG_STREAM_ENDPOINT 0x81u  /* bulk IN: the frame stream */
#define RIG_REQUEST_TYPE_IN 0xC0u  /* vendor, device, device to host */
#define RIG_REQUEST_TYPE_OUT 0x40u /* vendor, device, host to device */

#define RIG_PROTOCOL_VERSION 0x0102u
/* The version that added GET/SET_GEOMETRY, SET_SERIAL and ENTER_BOOTLOADER. */
#define RIG_GEOMETRY_VERSION 0x0101u
/* The version whose status says why the motor stopped, what restarted the device, and its health. */
#define RIG_FAULT_CAUSE_VERSION 0x0102u
/* ENTER_BOOTLOADER's wValue ("NB"): a stray request must not take the device off the bus. */
#define RIG_BOOTLOADER_KEY 0x4E42u

#define RIG_IDENTITY_BYTES 52u
#define RIG_STATUS_BYTES_1_0 16u /* 1.0 and 1.1; the least a status reply holds */
#define RIG_STATUS_BYTES 20u     /* 1.2 */
#define RIG_CALIBRATION_BYTES 12u
#define RIG_GEOMETRY_BYTES 8u
#define RIG_SERIAL_BYTES 16u
#define RIG_SPEED_BYTES 4u
#define RIG_POINT_BYTES 8u
#define RIG_MAX_POINTS_PER_REQUEST 8u
#define RIG_PACKET_HEADER_BYTES 4u
#define RIG_FRAME_BYTES 28u
#define RIG_MAX_FRAMES_PER_PACKET 18u /* a high-speed packet's 512 bytes */

enum rig_request {
  RIG_IDENTIFY = 0x01,
  RIG_GET_STATUS = 0x02,
  RIG_SET_STREAMING = 0x03,
  RIG_SET_SPEED = 0x10,
  RIG_START_PROFILE = 0x11,
  RIG_STOP = 0x12,
  RIG_PROFILE_BEGIN = 0x20,
  RIG_PROFILE_WRITE = 0x21,
  RIG_PROFILE_END = 0x22,
  RIG_PROFILE_READ = 0x23,
  RIG_ZERO_FORCE = 0x30,
  RIG_SET_FRAME_RATE = 0x31,
  RIG_GET_CALIBRATION = 0x32,
  RIG_SET_CALIBRATION = 0x33,
  RIG_GET_GEOMETRY = 0x34,
  RIG_SET_GEOMETRY = 0x35,
  RIG_SET_SERIAL = 0x36,
  RIG_ENTER_BOOTLOADER = 0x40
};

enum rig_refusal { RIG_REFUSE_NONE = 0, RIG_REFUSE_UNKNOWN = 1, RIG_REFUSE_LENGTH = 2, RIG_REFUSE_RANGE = 3, RIG_REFUSE_ORDER = 4 };
enum rig_mode { RIG_IDLE = 0, RIG_SPEED = 1, RIG_PROFILE = 2, RIG_PROFILE_DONE = 3 };
enum rig_fault { RIG_FAULT_NONE = 0, RIG_FAULT_MOTOR = 1, RIG_FAULT_ENCODER = 2, RIG_FAULT_WATCHDOG = 3, RIG_FAULT_FORCE = 4 };
/* Why the motor stopped (1.2): each cause belongs to one fault above (PROTOCOL.md "Fault causes"). */
enum rig_fault_cause {
  RIG_CAUSE_NONE = 0,
  RIG_CAUSE_STALL = 1,
  RIG_CAUSE_OVERCURRENT = 2,
  RIG_CAUSE_DRIVER = 3,
  RIG_CAUSE_SUPPLY = 4,
  RIG_CAUSE_OVERSPEED = 5,
  RIG_CAUSE_SLIP = 6,
  RIG_CAUSE_ENCODER_SILENT = 7,
  RIG_CAUSE_ENCODER_GLITCH = 8,
  RIG_CAUSE_ENCODER_REVERSED = 9,
  RIG_CAUSE_ENCODER_CHANNEL = 10,
  RIG_CAUSE_HOST_SILENT = 11,
  RIG_CAUSE_FORCE_SATURATED = 12,
  RIG_CAUSE_FORCE_NEGATIVE = 13
};
/* What restarted the controller last (1.2), from the chip's reset flags. */
enum rig_reset { RIG_RESET_POWER_ON = 0, RIG_RESET_EXTERNAL = 1, RIG_RESET_BROWN_OUT = 2, RIG_RESET_WATCHDOG = 3 };
enum rig_health { RIG_HEALTH_FACTORY_DEFAULTS = 1u << 0 };
/* A frame's flags (and the status's flags now). */
enum rig_flag {
  RIG_NORMAL_SATURATED = 1u << 0,
  RIG_TANGENTIAL_SATURATED = 1u << 1,
  RIG_ENCODER_FAULT = 1u << 2,
  RIG_MOTOR_FAULT = 1u << 3,
  RIG_WATCHDOG_STOPPED = 1u << 4,
  RIG_PROFILE_RUNNING = 1u << 5,
  RIG_FORCE_FAULT = 1u << 6
};

#endif
