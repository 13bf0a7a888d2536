// Which tablet model a device is, by libwacom's database, without claiming a model the device's USB
// id and name do not tell apart. Makers ship many models under one id (Huion's 256c:006d is listed
// for a dozen tablets): libwacom's lookup by id alone then names whichever entry it holds for the
// id, and its entries that also match the kernel's device name are the only way to tell them apart.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace nibrig::rig::pen {

// One of libwacom's match lines for a USB id: the model it names and the kernel device name it
// requires ("" when the id alone matches).
struct LibwacomMatch {
  std::string model;        // libwacom's model name, e.g. "Huion H640P"
  std::string device_name;  // e.g. "HUION Huion Tablet_H640P Pen"; "" for any name
  double width_mm = 0.0, height_mm = 0.0;  // libwacom's size (whole inches)
};

struct TabletModelName {
  // libwacom's model when the id and name tell it apart; when several models share the id and
  // the name matches none of them, a sentence saying so (the makers and the id), never a model.
  std::string model;
  bool told_apart = false;
  double width_mm = 0.0, height_mm = 0.0;  // the model's size; 0 unless told apart
};

// The choice, from the matches libwacom lists for the device's USB id: the model whose match line
// names the device's own name; else the one model the id is listed for; else no model but the
// sentence. Empty (and not told apart) when libwacom lists nothing for the id.
TabletModelName name_tablet_model(const std::vector<LibwacomMatch>& matches_for_id,
                                  const std::string& device_name, std::uint16_t vendor,
                                  std::uint16_t product);

// libwacom's match lines on the USB bus for vendor:product, from its installed database.
std::vector<LibwacomMatch> libwacom_usb_matches(std::uint16_t vendor, std::uint16_t product);

}  // namespace nibrig::rig::pen
