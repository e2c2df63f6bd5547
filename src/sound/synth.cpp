// The islands world's sounds, synthesized at start-up: waterfall, boat engine, propeller.
// Written by waterfall_noise / engine_hum / propeller_buzz, read by SoundScene::add_source.
//
// Every buffer is a seamless loop, because OpenAL repeats it end to start with no cross-fade:
//  * periodic parts have a whole number of cycles in the buffer and their phase is computed from
//    integers ((cycles * i) mod n), so sample n would equal sample 0 exactly;
//  * noise is filtered circularly (filter_circular), so the filter state at sample 0 is the one
//    the end of the loop leaves behind.
// Noise comes from a fixed-seed splitmix64, not <random> distributions, whose output the C++
// standard leaves to the implementation: the same call gives the same samples everywhere.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/sound.hpp"

namespace facet {
namespace {

constexpr int kSampleRate = 44100;
constexpr double kMaxSeconds = 60.0;
// Peak level after normalization: headroom below int16 full scale so rounding never clips.
constexpr double kPeak = 0.7;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::size_t sample_count(double seconds, const char* name) {
  if (!(seconds > 0.0 && seconds <= kMaxSeconds)) {
    throw Error(std::string(name) + ": seconds must be in (0, 60], got " + std::to_string(seconds));
  }
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(seconds * kSampleRate)));
}

// The whole number of cycles in n samples nearest to `hz` (at least one).
std::uint64_t loop_cycles(double hz, std::size_t n) {
  const double cycles = std::round(hz * static_cast<double>(n) / kSampleRate);
  return static_cast<std::uint64_t>(std::max(1.0, cycles));
}

// Phase in [0, 1) of sample i for a component with `cycles` cycles per loop of n samples; exact
// integer arithmetic, so no drift accumulates over long buffers (cycles * i < 2^40 here: at most
// 4 kHz * 60 s cycles times 60 s * 44100 samples).
double loop_phase(std::uint64_t cycles, std::size_t i, std::size_t n) {
  return static_cast<double>((cycles * i) % n) / static_cast<double>(n);
}

// splitmix64 (Steele, Lea, Flood 2014): tiny, fast, and well mixed even for sequential seeds.
class NoiseSource {
 public:
  explicit NoiseSource(std::uint64_t seed) : state_(seed) {}
  double next() {  // uniform in [-1, 1)
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-52 - 1.0;
  }

 private:
  std::uint64_t state_;
};

std::vector<double> white_noise(std::size_t n, std::uint64_t seed) {
  NoiseSource noise(seed);
  std::vector<double> x(n);
  for (double& v : x) v = noise.next();
  return x;
}

// Second-order low/high-pass, coefficients from R. Bristow-Johnson's "Audio EQ Cookbook";
// transposed direct form II.
struct Biquad {
  double b0, b1, b2, a1, a2;
  double z1 = 0.0, z2 = 0.0;

  double step(double x) {
    const double y = b0 * x + z1;
    z1 = b1 * x - a1 * y + z2;
    z2 = b2 * x - a2 * y;
    return y;
  }
};

Biquad make_biquad(double hz, bool high_pass) {
  const double q = std::numbers::sqrt2 / 2.0;  // Butterworth: flat pass band, no resonance
  const double w = kTwoPi * hz / kSampleRate;
  const double alpha = std::sin(w) / (2.0 * q);
  const double c = std::cos(w);
  const double a0 = 1.0 + alpha;
  const double b1 = high_pass ? -(1.0 + c) : 1.0 - c;
  const double b0 = high_pass ? (1.0 + c) / 2.0 : (1.0 - c) / 2.0;
  return Biquad{b0 / a0, b1 / a0, b0 / a0, -2.0 * c / a0, (1.0 - alpha) / a0};
}

// Filters x as if it repeated forever. Priming passes over the loop (at least 0.1 s, far longer
// than these filters' memory of a few milliseconds) leave the state the loop's end would leave;
// the output pass then starts from it, so y[0] follows y[n-1] as any sample follows the last.
void filter_circular(std::vector<double>& x, Biquad filter) {
  const std::size_t prime = std::max<std::size_t>(1, (kSampleRate / 10 + x.size()) / x.size());
  for (std::size_t pass = 0; pass < prime; ++pass) {
    for (double v : x) filter.step(v);
  }
  for (double& v : x) v = filter.step(v);
}

std::vector<double> band_noise(std::size_t n, std::uint64_t seed, double low_hz, double high_hz) {
  std::vector<double> x = white_noise(n, seed);
  filter_circular(x, make_biquad(high_hz, false));
  filter_circular(x, make_biquad(low_hz, true));
  return x;
}

// Scales to kPeak of full scale and rounds to 16 bits.
SoundBuffer to_pcm(const std::vector<double>& x) {
  double peak = 0.0;
  for (double v : x) peak = std::max(peak, std::abs(v));
  const double scale = peak > 0.0 ? kPeak * 32767.0 / peak : 0.0;
  SoundBuffer out;
  out.sample_rate = kSampleRate;
  out.samples.resize(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    out.samples[i] = static_cast<std::int16_t>(std::lround(x[i] * scale));
  }
  return out;
}

}  // namespace

SoundBuffer waterfall_noise(double seconds) {
  const std::size_t n = sample_count(seconds, "waterfall_noise");
  // Falling water is broadband: a roar (60-400 Hz) under a hiss (300-3000 Hz).
  const std::vector<double> roar = band_noise(n, 0x57a7e4f411ull, 60.0, 400.0);
  const std::vector<double> hiss = band_noise(n, 0x5b1a5411ull, 300.0, 3000.0);
  // The swell: two slow, unrelated sways of loudness, so the loop does not sound like a loop.
  const std::uint64_t sway1 = loop_cycles(0.23, n), sway2 = loop_cycles(0.61, n);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double swell = 1.0 + 0.18 * std::sin(kTwoPi * loop_phase(sway1, i, n)) +
                         0.10 * std::sin(kTwoPi * loop_phase(sway2, i, n) + 1.3);
    x[i] = swell * (1.6 * roar[i] + hiss[i]);
  }
  return to_pcm(x);
}

SoundBuffer engine_hum(double seconds) {
  const std::size_t n = sample_count(seconds, "engine_hum");
  const std::uint64_t base = loop_cycles(50.0, n);  // firing tone
  const std::uint64_t putt = loop_cycles(6.0, n);   // the putt-putt: pulses per second
  const std::vector<double> rattle = band_noise(n, 0xb0a7ull, 80.0, 600.0);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    double tone = 0.0;
    for (std::uint64_t h = 1; h <= 8; ++h) {  // harmonics fall off as 1/h: a dull, round tone
      tone += std::sin(kTwoPi * loop_phase(base * h, i, n) + 0.7 * static_cast<double>(h)) /
              static_cast<double>(h);
    }
    // Each pulse: an alpha-function envelope (p/a)e^(1-p/a), zero at the pulse's start and
    // peaking at p = a, so pulses start without a click; 10e^-9 (0.1%) is left at the next.
    const double p = loop_phase(putt, i, n) / 0.1;
    const double pulse = p * std::exp(1.0 - p);
    x[i] = (0.3 + 0.7 * pulse) * (tone + 0.35 * rattle[i]);
  }
  return to_pcm(x);
}

SoundBuffer propeller_buzz(double seconds) {
  const std::size_t n = sample_count(seconds, "propeller_buzz");
  const std::uint64_t base = loop_cycles(104.0, n);  // engine firing rate
  const std::uint64_t blade = loop_cycles(26.0, n);  // blade passing rate (2 blades)
  const std::vector<double> air = band_noise(n, 0xa1eull, 800.0, 4000.0);
  // A band-limited sawtooth, sum of sin(h x) / h over harmonics up to 4 kHz (none to alias),
  // started half a period on (x + pi: the sign of odd harmonics flips) so the loop begins
  // mid-ramp rather than on the saw's drop. sin(h x) comes from the angle-addition recurrence,
  // not one std::sin per harmonic, which would be dear with dozens of harmonics a sample.
  const std::uint64_t harmonics = std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(4000.0 * static_cast<double>(n) / kSampleRate) / base);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = kTwoPi * loop_phase(base, i, n);
    const double c = std::cos(angle), s = std::sin(angle);
    double sin_h = s, cos_h = c;  // sin(h x), cos(h x) for h = 1
    double saw = 0.0;
    for (std::uint64_t h = 1; h <= harmonics; ++h) {
      saw += (h % 2 == 1 ? -sin_h : sin_h) / static_cast<double>(h);
      const double next_sin = sin_h * c + cos_h * s;
      cos_h = cos_h * c - sin_h * s;
      sin_h = next_sin;
    }
    // Each blade passing the listener's side swells the buzz: a raised cosine at blade rate.
    const double swish = 0.65 + 0.35 * (0.5 + 0.5 * std::cos(kTwoPi * loop_phase(blade, i, n)));
    x[i] = swish * (saw + 0.15 * air[i]);
  }
  return to_pcm(x);
}

}  // namespace facet
