#include "tests/rig/usb/avr109_bootloader.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>

namespace nibrig::rig::usb::testing {

Avr109Bootloader::Avr109Bootloader(int fd, std::array<std::uint8_t, 3> signature)
    : fd_(fd), signature_(signature), flash_(kFlashBytes, 0xFF) {
  thread_ = std::thread([this] { serve(); });
}

Avr109Bootloader::~Avr109Bootloader() {
  stop_ = true;
  thread_.join();
}

std::vector<std::uint8_t> Avr109Bootloader::flash() const {
  std::lock_guard lock(mutex_);
  return flash_;
}

std::string Avr109Bootloader::commands() const {
  std::lock_guard lock(mutex_);
  return commands_;
}

// Waits in short polls so that the destructor is noticed; false when stopping.
bool Avr109Bootloader::read_bytes(std::uint8_t* into, std::size_t n) {
  std::size_t got = 0;
  while (got < n) {
    if (stop_) return false;
    pollfd p{fd_, POLLIN, 0};
    if (poll(&p, 1, 20) <= 0) continue;
    const ssize_t r = read(fd_, into + got, n - got);
    if (r > 0) {
      got += static_cast<std::size_t>(r);
    } else if (r < 0 && errno != EAGAIN && errno != EINTR && errno != EIO) {
      return false;
    } else if (r <= 0) {
      usleep(5000);  // EIO: nobody has the slave side open yet
    }
  }
  return true;
}

void Avr109Bootloader::reply(const std::uint8_t* bytes, std::size_t n) {
  std::size_t sent = 0;
  while (sent < n) {
    const ssize_t w = write(fd_, bytes + sent, n - sent);
    if (w > 0) {
      sent += static_cast<std::size_t>(w);
    } else if (errno != EAGAIN && errno != EINTR) {
      return;
    }
  }
}

void Avr109Bootloader::reply(std::initializer_list<std::uint8_t> bytes) { reply(bytes.begin(), bytes.size()); }

// The commands Caterina answers (AVR109 with LUFA's extensions), as avrdude's avr109 programmer
// uses them; anything else gets '?', as on the board.
void Avr109Bootloader::serve() {
  std::uint8_t c = 0;
  while (!exited_ && read_bytes(&c, 1)) {
    {
      std::lock_guard lock(mutex_);
      commands_ += static_cast<char>(c);
    }
    switch (c) {
      case 0x1B: break;  // sync: no answer
      case 'S': reply({'C', 'A', 'T', 'E', 'R', 'I', 'N'}); break;
      case 'V': reply({'1', '0'}); break;
      case 'p': reply({'S'}); break;  // a serial programmer
      case 'a': reply({'Y'}); break;  // auto-increments the address
      case 'b': reply({'Y', 0x00, static_cast<std::uint8_t>(kPageBytes)}); break;
      case 't': reply({0x44, 0x00}); break;  // the one device type, then the list's end
      case 's': reply({signature_[2], signature_[1], signature_[0]}); break;  // last byte first
      case 'T': {
        std::uint8_t type = 0;
        if (!read_bytes(&type, 1)) return;
        reply({'\r'});
        break;
      }
      case 'P': case 'L': case 'x': case 'y': reply({'\r'}); break;
      case 'e': {
        std::lock_guard lock(mutex_);
        std::fill(flash_.begin(), flash_.end(), std::uint8_t{0xFF});
        reply({'\r'});
        break;
      }
      case 'A': {
        std::uint8_t a[2];
        if (!read_bytes(a, 2)) return;
        address_ = static_cast<std::size_t>((a[0] << 8) | a[1]) * 2;
        reply({'\r'});
        break;
      }
      case 'B': case 'g': {
        std::uint8_t h[3];
        if (!read_bytes(h, 3)) return;
        const std::size_t n = static_cast<std::size_t>((h[0] << 8) | h[1]);
        const bool flash_memory = h[2] == 'F';
        if (c == 'B') {
          std::vector<std::uint8_t> data(n);
          if (!read_bytes(data.data(), n)) return;
          if (flash_memory) {
            std::lock_guard lock(mutex_);
            for (std::size_t i = 0; i < n && address_ < kFlashBytes; ++i) flash_[address_++] = data[i];
          }
          reply({'\r'});
        } else {
          std::vector<std::uint8_t> data(n, 0xFF);
          if (flash_memory) {
            std::lock_guard lock(mutex_);
            for (std::size_t i = 0; i < n && address_ < kFlashBytes; ++i) data[i] = flash_[address_++];
          }
          reply(data.data(), n);
        }
        break;
      }
      case 'r': case 'F': case 'N': case 'Q': reply({0xFF}); break;  // lock and fuse bits
      case 'E':
        reply({'\r'});
        exited_ = true;
        break;
      default: reply({'?'}); break;
    }
  }
}

}  // namespace nibrig::rig::usb::testing
