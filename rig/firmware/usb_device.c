#include "usb_device.h"

#include <avr/io.h>
#include <avr/pgmspace.h>
#include "board.h"
#include "frame_fifo.h"
#include "rig_protocol.h"

#define EP0_SIZE 64u
#define STREAM_EP 1u

static const uint8_t device_descriptor[18] PROGMEM = {
    18, 1, 0x00, 0x02,       /* USB 2.0 */
    0xFF, 0x00, 0x00,        /* vendor specific */
    EP0_SIZE,
    RIG_USB_VENDOR_ID & 0xFFu, RIG_USB_VENDOR_ID >> 8,
    RIG_USB_PRODUCT_ID & 0xFFu, RIG_USB_PRODUCT_ID >> 8,
    0x10, 0x01,              /* bcdDevice 1.10: the firmware's version */
    1, 2, 3, 1};             /* manufacturer, product, serial strings; one configuration */

static const uint8_t configuration_descriptor[25] PROGMEM = {
    9, 2, 25, 0, 1, 1, 0, 0x80, 50,        /* one interface, bus powered, 100 mA */
    9, 4, 0, 0, 1, 0xFF, 0x00, 0x00, 0,    /* interface 0: one endpoint, vendor specific */
    7, 5, RIG_STREAM_ENDPOINT, 0x02, 64, 0, 0}; /* bulk IN, 64 bytes (full speed) */

static const char manufacturer[] PROGMEM = "nibrig";
static const char product[] PROGMEM = "nibrig rig controller";

static usb_vendor_handler vendor;
static const char *serial_number;
static uint8_t configured;
static uint8_t streaming_packet; /* a packet is on its way */

void usb_device_init(usb_vendor_handler handler, const char *serial) {
  vendor = handler;
  serial_number = serial;
  UHWCON = (1 << UVREGE);
  USBCON = (1 << USBE) | (1 << FRZCLK);
  PLLCSR = (1 << PINDIV) | (1 << PLLE); /* 16 MHz crystal / 2 into the 48 MHz PLL */
  while (!(PLLCSR & (1 << PLOCK))) {
  }
  USBCON = (1 << USBE) | (1 << OTGPADE);
  UDCON = 0; /* attach, full speed */
}

static void configure_ep0(void) {
  UENUM = 0;
  UECONX = (1 << EPEN);
  UECFG0X = 0; /* control */
  UECFG1X = (1 << EPSIZE1) | (1 << EPSIZE0) | (1 << ALLOC); /* 64 bytes */
}

static void configure_stream(void) {
  UENUM = STREAM_EP;
  UECONX = (1 << EPEN);
  UECFG0X = (1 << EPTYPE1) | (1 << EPDIR); /* bulk IN */
  UECFG1X = (1 << EPSIZE1) | (1 << EPSIZE0) | (1 << EPBK0) | (1 << ALLOC); /* 64 bytes, two banks */
  UERST = (1 << STREAM_EP);
  UERST = 0;
  streaming_packet = 0;
  UENUM = 0;
}

/* A host carries each stage of a control transfer within microseconds of the last; one that has
 * not in 20 ms is gone (a killed process, a pulled cable), and the loop must go on: the speed loop,
 * the frames and the protocol's watchdog run only there. */
#define EP0_STAGE_LIMIT_US 20000u

/* Waits for one of EP0's `bits`; 0 when a bus reset or a new SETUP came first (the transfer is
 * over: a host may send the next SETUP before the device has seen the last status stage), or when
 * the host has not gone on within EP0_STAGE_LIMIT_US. */
static uint8_t ep0_wait(uint8_t bits) {
  const uint32_t start = (uint32_t)board_clock_us();
  for (;;) {
    const uint8_t flags = UEINTX;
    if (flags & bits) return flags;
    if ((flags & (1 << RXSTPI)) || (UDINT & (1 << EORSTI))) return 0;
    if ((uint32_t)board_clock_us() - start > EP0_STAGE_LIMIT_US) return 0;
  }
}

static void ep0_status_in(void) {
  if (ep0_wait(1 << TXINI)) UEINTX = (uint8_t) ~(1 << TXINI);
}

static void ep0_stall(void) { UECONX |= (1 << STALLRQ); }

/* An IN data stage from RAM or flash, then the host's status stage. */
static void ep0_send(const uint8_t *data, uint16_t length, uint16_t requested, uint8_t from_flash) {
  if (length > requested) length = requested;
  do {
    const uint8_t flags = ep0_wait((1 << TXINI) | (1 << RXOUTI));
    if (!flags || (flags & (1 << RXOUTI))) break; /* reset, or the host ended the data stage */
    const uint8_t n = length < EP0_SIZE ? (uint8_t)length : EP0_SIZE;
    for (uint8_t i = 0; i < n; ++i) UEDATX = from_flash ? pgm_read_byte(data + i) : data[i];
    data += n;
    length -= n;
    UEINTX = (uint8_t) ~(1 << TXINI);
  } while (length > 0);
  if (ep0_wait(1 << RXOUTI)) UEINTX = (uint8_t) ~(1 << RXOUTI);
}

/* A string descriptor in UTF-16LE from an ASCII string in RAM or flash. */
static void send_string(const char *s, uint8_t from_flash, uint16_t requested) {
  uint8_t d[2 + 2 * 24];
  uint8_t n = 0;
  while (n < 24) {
    const char c = from_flash ? (char)pgm_read_byte(s + n) : s[n];
    if (c == 0 || (!from_flash && n >= RIG_SERIAL_BYTES)) break;
    d[2 + 2 * n] = (uint8_t)c;
    d[3 + 2 * n] = 0;
    ++n;
  }
  d[0] = (uint8_t)(2 + 2 * n);
  d[1] = 3;
  ep0_send(d, d[0], requested, 0);
}

static void get_descriptor(uint16_t value, uint16_t requested) {
  const uint8_t type = (uint8_t)(value >> 8), index = (uint8_t)value;
  if (type == 1) {
    ep0_send(device_descriptor, sizeof device_descriptor, requested, 1);
  } else if (type == 2) {
    ep0_send(configuration_descriptor, sizeof configuration_descriptor, requested, 1);
  } else if (type == 3 && index == 0) {
    static const uint8_t languages[4] PROGMEM = {4, 3, 0x09, 0x04}; /* English (US) */
    ep0_send(languages, sizeof languages, requested, 1);
  } else if (type == 3 && index == 1) {
    send_string(manufacturer, 1, requested);
  } else if (type == 3 && index == 2) {
    send_string(product, 1, requested);
  } else if (type == 3 && index == 3) {
    send_string(serial_number, 0, requested);
  } else {
    ep0_stall();
  }
}

static void standard_request(const uint8_t *setup) {
  const uint8_t request = setup[1];
  const uint16_t value = (uint16_t)(setup[2] | (setup[3] << 8));
  const uint16_t index = (uint16_t)(setup[4] | (setup[5] << 8));
  const uint16_t length = (uint16_t)(setup[6] | (setup[7] << 8));
  static const uint8_t zeros[2] PROGMEM = {0, 0};
  switch (request) {
    case 6: get_descriptor(value, length); return;
    case 5: /* SET_ADDRESS: the address takes effect after the status stage */
      UDADDR = (uint8_t)(value & 0x7F);
      UEINTX = (uint8_t) ~(1 << TXINI);
      ep0_wait(1 << TXINI);
      UDADDR |= (1 << ADDEN);
      return;
    case 9: /* SET_CONFIGURATION */
      configured = (uint8_t)value == 1;
      if (configured) configure_stream();
      ep0_status_in();
      return;
    case 8: ep0_send(&configured, 1, length, 0); return;
    case 0: ep0_send(zeros, 2, length, 1); return; /* GET_STATUS */
    case 11: ep0_status_in(); return;                /* SET_INTERFACE: one setting */
    case 1:                                          /* CLEAR_FEATURE(ENDPOINT_HALT) */
      if ((setup[0] & 0x1F) == 2 && (index & 0x7F) == STREAM_EP) {
        UENUM = STREAM_EP;
        UECONX |= (1 << STALLRQC) | (1 << RSTDT);
        UENUM = 0;
        ep0_status_in();
        return;
      }
      ep0_stall();
      return;
    default: ep0_stall(); return;
  }
}

static enum usb_event vendor_request(const uint8_t *setup) {
  const uint16_t length = (uint16_t)(setup[6] | (setup[7] << 8));
  static struct rig_reply reply;
  uint8_t data[64];
  if (!(setup[0] & 0x80) && length > 0) {
    if (length > sizeof data) { /* no request carries more: refused without reading it */
      vendor(setup, 0, &reply);
      ep0_stall();
      return USB_NOTHING;
    }
    if (!ep0_wait(1 << RXOUTI)) return USB_NOTHING;
    for (uint8_t i = 0; i < length; ++i) data[i] = UEDATX;
    UEINTX = (uint8_t) ~(1 << RXOUTI);
  }
  vendor(setup, data, &reply);
  if (reply.stall) {
    ep0_stall();
  } else if (setup[0] & 0x80) {
    ep0_send(reply.data, reply.len, length, 0);
  } else {
    ep0_status_in();
  }
  return reply.bootloader ? USB_BOOTLOADER_ASKED : USB_NOTHING;
}

enum usb_event usb_device_poll(void) {
  if (UDINT & (1 << EORSTI)) {
    UDINT &= (uint8_t) ~(1 << EORSTI);
    configured = 0;
    configure_ep0();
    return USB_BUS_RESET;
  }
  UENUM = 0;
  if (!(UEINTX & (1 << RXSTPI))) return USB_NOTHING;
  uint8_t setup[8];
  for (uint8_t i = 0; i < 8; ++i) setup[i] = UEDATX;
  UEINTX = (uint8_t) ~(1 << RXSTPI);
  if ((setup[0] & 0x60) == 0x40) return vendor_request(setup);
  standard_request(setup);
  return USB_NOTHING;
}

int usb_device_configured(void) { return configured; }

int usb_stream_idle(void) { return !streaming_packet; }

void usb_stream_start(void) { streaming_packet = 1; }

void usb_stream_service(struct frame_fifo *fifo) {
  if (!configured || !streaming_packet) return;
  UENUM = STREAM_EP;
  if (UEINTX & (1 << TXINI)) {
    UEINTX = (uint8_t) ~(1 << TXINI);
    uint8_t room = 64u;
    const uint8_t *bytes;
    uint8_t n;
    while (room > 0 && (n = frame_fifo_packet_span(fifo, &bytes)) > 0) {
      if (n > room) n = room;
      for (uint8_t i = 0; i < n; ++i) UEDATX = bytes[i];
      frame_fifo_packet_advance(fifo, n);
      room = (uint8_t)(room - n);
    }
    UEINTX = (uint8_t) ~(1 << FIFOCON);
    /* A USB packet shorter than 64 bytes ends the transfer: the packet is all sent. */
    if (room > 0) streaming_packet = 0;
  }
  UENUM = 0;
}
