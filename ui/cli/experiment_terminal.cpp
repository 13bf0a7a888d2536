#include "ui/cli/experiment_terminal.hpp"

#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

namespace nibrig::ui::cli {

namespace study = model::study;

struct TerminalParticipant::Saved {
  termios settings{};
};

TerminalParticipant::TerminalParticipant(int in, std::FILE* out) : in_(in), out_(out) {
  if (::isatty(in_)) {
    saved_ = new Saved;
    if (::tcgetattr(in_, &saved_->settings) == 0) {
      termios raw = saved_->settings;
      raw.c_lflag &= static_cast<tcflag_t>(~(ICANON | ECHO));
      raw.c_cc[VMIN] = 1;
      raw.c_cc[VTIME] = 0;
      raw_ = ::tcsetattr(in_, TCSANOW, &raw) == 0;
    }
  }
}

TerminalParticipant::~TerminalParticipant() {
  if (raw_) ::tcsetattr(in_, TCSANOW, &saved_->settings);
  delete saved_;
}

int TerminalParticipant::key() {
  std::fflush(out_);
  if (raw_) {
    char c = 0;
    for (;;) {
      const ssize_t n = ::read(in_, &c, 1);
      if (n == 1) return c == '\r' ? '\n' : static_cast<unsigned char>(c);
      if (n < 0 && errno == EINTR) continue;
      return EOF;
    }
  }
  // A pipe: one key per line, its first character that is not a space; an empty line is Enter.
  std::string line;
  char c = 0;
  for (;;) {
    const ssize_t n = ::read(in_, &c, 1);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (line.empty()) return EOF;
      break;
    }
    if (c == '\n') break;
    line.push_back(c);
  }
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string::npos ? '\n' : static_cast<unsigned char>(line[first]);
}

bool TerminalParticipant::wait_for_enter() {
  for (;;) {
    const int k = key();
    if (k == EOF) return false;
    if (k == '\n' || k == ' ') return true;
  }
}

bool TerminalParticipant::agree(const study::StudyTexts& texts) {
  std::fprintf(out_, "\n%s\n%s\nType y to agree and start, anything else to stop: ",
               texts.instructions.c_str(), texts.consent.c_str());
  const int k = key();
  std::fprintf(out_, "\n");
  return k == 'y' || k == 'Y';
}

study::Answer TerminalParticipant::answer(const study::TrialPrompt& prompt,
                                          const std::function<void(study::Role)>& play) {
  std::fprintf(out_, "\nTrial %zu of at most %zu%s\n  r: reference   a: A   b: B   "
               "(as often as you like)\n  1: A is closer to the reference   2: B is closer   "
               "q: stop for now\n",
               prompt.number, prompt.expected_at_most, prompt.planned.practice ? " (practice)" : "");
  bool felt[3] = {false, false, false};
  for (;;) {
    const int k = key();
    switch (k) {
      case 'r':
      case 'R':
        play(study::Role::reference), felt[0] = true;
        std::fprintf(out_, "  playing the reference\n");
        break;
      case 'a':
      case 'A':
        play(study::Role::left), felt[1] = true;
        std::fprintf(out_, "  playing A\n");
        break;
      case 'b':
      case 'B':
        play(study::Role::right), felt[2] = true;
        std::fprintf(out_, "  playing B\n");
        break;
      case '1':
      case '2':
        if (!(felt[0] && felt[1] && felt[2])) {
          std::fprintf(out_, "  feel the reference, A and B first (r, a, b)\n");
          break;
        }
        std::fprintf(out_, "  %s is closer\n", k == '1' ? "A" : "B");
        return {k == '1' ? model::space::Choice::left : model::space::Choice::right, std::nullopt};
      case 'q':
      case 'Q':
      case EOF:
        std::fprintf(out_, "  stopped: this trial is not recorded; --resume continues with it\n");
        return {};
      default:
        break;  // Enter, spaces and other keys do nothing
    }
  }
}

void TerminalParticipant::rest(std::size_t done, std::size_t expected_at_most) {
  std::fprintf(out_, "\n%zu of at most %zu trials done. Take a rest; press Enter to go on.\n", done,
               expected_at_most);
  wait_for_enter();
}

}  // namespace nibrig::ui::cli
