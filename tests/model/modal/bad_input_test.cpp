// Every entry point rejects what it cannot integrate with std::invalid_argument, and the message
// names the caller, the field (with its index) and the offending value, as ARCHITECTURE.md ("Conventions") asks of API
// boundaries.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/modal/frequency_response.hpp"
#include "model/modal/linear_forcing_integrator.hpp"
#include "model/modal/modal_oscillator.hpp"
#include "model/modal/response_basis.hpp"
#include "model/modal/sinusoid_step.hpp"

namespace nibrig::model::modal {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

ModalModel good() {
  return {{100.0, 2000.0, 9000.0}, {0.1, 1.0, 4.0}, {1.0, -0.5, 0.2}, {0.3, 0.8, -1.0}};
}

// Calls f and returns the message of the std::invalid_argument it must throw ("" and a failure if
// it throws nothing or something else).
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  } catch (...) {
    ADD_FAILURE() << "threw something other than std::invalid_argument";
    return "";
  }
  ADD_FAILURE() << "did not throw";
  return "";
}

// One bad model through every constructor and function that takes a model.
void expect_model_rejected(const ModalModel& m, const std::vector<std::string>& words) {
  const Sinusoid s{1.0, 100.0, 0.0};
  const std::vector<double> f = {100.0};
  const std::vector<std::function<void()>> calls = {
      [&] { LinearForcingIntegrator(m, 48000.0); },
      [&] {
        simulate_sinusoids(m, {&s, 1}, 48000.0, 10);
      },
      [&] { FrequencyResponseBasis(m, 48000.0, 10, f); },
      [&] { frequency_response(m, f); },
  };
  const std::vector<std::string> callers = {"LinearForcingIntegrator", "simulate_sinusoids",
                                            "FrequencyResponseBasis", "frequency_response"};
  for (std::size_t c = 0; c < calls.size(); ++c) {
    const std::string what = message_of(calls[c]);
    EXPECT_THAT(what, HasSubstr(callers[c]));
    for (const auto& w : words) EXPECT_THAT(what, HasSubstr(w)) << callers[c];
  }
}

TEST(BadInput, NegativeZeroOrNonFiniteOmega) {
  ModalModel m = good();
  m.omega[1] = -3.0;
  expect_model_rejected(m, {"omega[1]", "-3", "> 0"});
  m.omega[1] = 0.0;
  expect_model_rejected(m, {"omega[1]", "= 0", "> 0"});
  m.omega[1] = kNan;
  expect_model_rejected(m, {"omega[1]", "nan"});
  m.omega[1] = kInf;
  expect_model_rejected(m, {"omega[1]", "inf"});
}

TEST(BadInput, NegativeOrNonFiniteZetaAndNonFiniteCouplings) {
  ModalModel m = good();
  m.zeta[2] = -0.01;
  expect_model_rejected(m, {"zeta[2]", "-0.01", ">= 0"});
  m = good();
  m.zeta[0] = kNan;
  expect_model_rejected(m, {"zeta[0]", "nan"});
  m = good();
  m.input[1] = kInf;
  expect_model_rejected(m, {"input[1]", "inf", "finite"});
  m = good();
  m.output[2] = -kNan;
  expect_model_rejected(m, {"output[2]", "nan", "finite"});
}

TEST(BadInput, MismatchedOrEmptyModel) {
  ModalModel m = good();
  m.zeta.pop_back();
  expect_model_rejected(m, {"zeta", "2 entries, expected 3"});
  m = good();
  m.output.push_back(1.0);
  expect_model_rejected(m, {"output", "4 entries, expected 3"});
  expect_model_rejected(ModalModel{}, {"no modes"});
}

TEST(BadInput, NonPositiveOrNonFiniteSampleRate) {
  const ModalModel m = good();
  const Sinusoid s{1.0, 100.0, 0.0};
  for (double rate : {0.0, -48000.0, kNan, kInf}) {
    for (const auto& call : std::vector<std::function<void()>>{
             [&] { LinearForcingIntegrator(m, rate); },
             [&] {
               simulate_sinusoids(m, {&s, 1}, rate, 10);
             },
             [&] { FrequencyResponseBasis(m, rate, 10, {100.0}); }}) {
      EXPECT_THAT(message_of(call),
                  AllOf(HasSubstr("sample rate"), HasSubstr("Hz"), HasSubstr("> 0")))
          << "rate " << rate;
    }
  }
}

TEST(BadInput, SinusoidsAndFrequencies) {
  const ModalModel m = good();
  auto simulate = [&](Sinusoid s) {
    return message_of([&] { simulate_sinusoids(m, {&s, 1}, 48000.0, 4); });
  };
  EXPECT_THAT(simulate({kNan, 100.0, 0.0}),
              AllOf(HasSubstr("sinusoid 0 amplitude"), HasSubstr("nan")));
  EXPECT_THAT(simulate({1.0, kInf, 0.0}),
              AllOf(HasSubstr("sinusoid 0 frequency"), HasSubstr("inf")));
  EXPECT_THAT(simulate({1.0, 100.0, kNan}), HasSubstr("sinusoid 0 phase"));
  EXPECT_THAT(simulate({1.0, -5.0, 0.0}), AllOf(HasSubstr("frequency -5 Hz"), HasSubstr(">= 0")));
  EXPECT_THAT(message_of([&] {
                frequency_response(m, std::vector<double>{10.0, -1.0});
              }),
              AllOf(HasSubstr("frequency 1 = -1 Hz"), HasSubstr(">= 0")));
  EXPECT_THAT(
      message_of([&] {
        FrequencyResponseBasis(m, 48000.0, 4, {10.0, kNan});
      }),
      AllOf(HasSubstr("FrequencyResponseBasis"), HasSubstr("frequency 1"), HasSubstr("nan")));
  // The one frequency where H does not exist: the resonance of an undamped mode.
  ModalModel undamped = good();
  undamped.zeta[0] = 0.0;
  const double resonance = undamped.omega[0] / (2.0 * 3.14159265358979323846);
  EXPECT_THAT(message_of([&] { frequency_response(undamped, std::vector<double>{resonance}); }),
              AllOf(HasSubstr("resonance of undamped mode 0"), HasSubstr("infinite")));
}

TEST(BadInput, SynthesisAndStateSizes) {
  const ModalModel m = good();
  const FrequencyResponseBasis basis(m, 48000.0, 8, {10.0, 20.0, 30.0});
  const std::vector<double> two = {1.0, 1.0}, three = {1.0, 1.0, 1.0};
  EXPECT_THAT(
      message_of([&] { basis.synthesize(two, three); }),
      AllOf(HasSubstr("synthesize"), HasSubstr("amplitudes"), HasSubstr("2 entries, expected 3")));
  EXPECT_THAT(message_of([&] { basis.synthesize(three, two); }),
              AllOf(HasSubstr("phases"), HasSubstr("2 entries, expected 3")));
  const std::vector<double> bad = {1.0, kInf, 1.0};
  EXPECT_THAT(message_of([&] { basis.synthesize(bad, three); }),
              AllOf(HasSubstr("amplitude 1"), HasSubstr("inf")));
  EXPECT_THROW(static_cast<void>(basis.sine_response(3)), std::out_of_range);

  LinearForcingIntegrator e(m, 48000.0);
  EXPECT_THAT(
      message_of([&] { e.set_state(two, three, 0.0); }),
      AllOf(HasSubstr("set_state"), HasSubstr("displacement"), HasSubstr("2 entries, expected 3")));
  EXPECT_THAT(message_of([&] { e.set_state(three, three, kNan); }),
              AllOf(HasSubstr("force"), HasSubstr("nan")));
  EXPECT_THAT(message_of([&] { e.set_state(three, bad, 0.0); }),
              AllOf(HasSubstr("velocity[1]"), HasSubstr("inf")));
  EXPECT_THAT(message_of([&] { impulse_response_moment(1.0, 0.1, 0.01, 2); }),
              HasSubstr("power must be 0 or 1"));
}

}  // namespace
}  // namespace nibrig::model::modal
