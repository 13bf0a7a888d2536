/* The ATmega32U4's USB device controller as PROTOCOL.md's vendor-class device: enumeration on
 * EP0, vendor requests handed to the rig, and the frame stream's packets on bulk IN 0x81. Polled
 * from the main loop; nothing here runs in an interrupt. */
#ifndef NIBRIG_USB_DEVICE_H
#define NIBRIG_USB_DEVICE_H

#include <stdint.h>

#include "frame_fifo.h"
#include "rig_device.h"

/* What a vendor request does: answer it into `reply` (the rig's own call). `data` is the OUT data
 * stage, or 0 when the request announced more data than any request carries. */
typedef void (*usb_vendor_handler)(const uint8_t setup[8], const uint8_t *data, struct rig_reply *reply);

void usb_device_init(usb_vendor_handler handler, const char *serial);
enum usb_event { USB_NOTHING = 0, USB_BUS_RESET, USB_BOOTLOADER_ASKED };
/* Bus reset and EP0's requests. */
enum usb_event usb_device_poll(void);
int usb_device_configured(void);
/* The frame stream: whether the last packet is all sent; starting to send the packet `fifo` has
 * begun (frame_fifo_begin_packet). */
int usb_stream_idle(void);
void usb_stream_start(void);
/* Moves the packet in progress on by one USB packet when the endpoint's bank is free, read straight
 * out of the ring. */
void usb_stream_service(struct frame_fifo *fifo);

#endif
