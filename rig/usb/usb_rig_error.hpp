// The one exception type of the USB rig controller: what was asked of which device and why it
// could not be done (missing, unplugged, refused a request, a reply that breaks PROTOCOL.md), in
// words a user can act on. Thrown on control threads only; the event thread records, never throws.
#pragma once

#include <stdexcept>

namespace nibrig::rig::usb {

class UsbRigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace nibrig::rig::usb
