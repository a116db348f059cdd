// Where the sounds in one block of ear signals come from. The block is cut
// into short Hann-windowed frames; in each frame every band that is loud
// enough votes for the azimuths whose templates match what it hears:
//  - up to the layout's phase_high_hz, the interaural phase of its FFT bins,
//    weighed by their cross-power and steered to each azimuth's template
//    phase (the GCC-PHAT of the band evaluated at that azimuth's interaural
//    delay, with the template's own phase per bin rather than one delay for
//    all); between joint_level_from_hz and joint_level_to_hz together with
//    the bin's level difference;
//  - above the split frequency, also the interaural level difference of the
//    band against the template's, with a spread that allows for a head not
//    quite like the template's.
// Each vote is a distribution over azimuth, weighted by the band's amplitude
// (the square root of its energy, so a quieter source still shows). Sources
// that dominate different frames and bands give separate peaks. Silent
// blocks and bands do not vote: a silent block gives a flat posterior and no
// peaks.
#pragma once

#include <vector>

#include "lib/hearing/azimuth_posterior.hpp"
#include "lib/hearing/azimuth_votes.hpp"
#include "lib/hearing/band_signature.hpp"
#include "lib/hearing/interaural_templates.hpp"
#include "lib/hearing/fft_convolver.hpp"

namespace beft::hearing {

struct LocaliserConfig {
  // A frame votes only if its RMS over both ears is at least this (-60 dBFS;
  // the rendered noise floor is -80 dBFS).
  double silence_rms = 1e-3;
  // A band votes only if its power per bin is within this of the block's
  // loudest band and above what white noise at silence_rms would give it.
  double band_range_db = 50;
  // Concentration of a bin's phase vote, exp(k (cos(heard - template) - 1)),
  // at the reference frequency; it grows as 1/f below it, up to the maximum.
  double phase_sharpness = 8;
  double sharpness_reference_hz = 1000;
  double max_phase_sharpness = 200;
  // Spread of a level band's vote around the template's ILD [dB]: wide,
  // since ILDs above a few kHz differ by up to 10 dB between two KEMARs.
  double ild_spread_db = 9;
  // Weight of a level vote against a time vote of the same energy: the
  // level cues help beside the head, where time cues change least, but
  // carry the other head's pinna with them.
  double level_cue_weight = 0.3;
  // Between these frequencies [Hz] a bin's phase vote also weighs the bin's
  // own level difference against the template's (one likelihood for both,
  // since they come from the same source): from about 700 Hz the interaural
  // phase of a tone fits several azimuths (a period is shorter than the
  // range of ITDs), and a few dB of level tell them apart; above 3 kHz the
  // two heads' level differences disagree too much to sharpen anything.
  double joint_level_from_hz = 700;
  double joint_level_to_hz = 3000;
  double joint_ild_spread_db = 9;
  // A vote weighs energy^weight_exponent: 0.5 (its amplitude) lets a quieter
  // or narrower-band source still show beside a loud broadband one.
  double weight_exponent = 0.5;
  // Interaural-coherence cue selection (Faller and Merimaa 2004, JASA
  // 116(5), eqs. 6-8): a bin's time cue votes with the weight
  // ((c - floor) / (1 - floor))^exponent, c its interaural coherence
  // |<X_L X_R*>| / sqrt(<|X_L|^2> <|X_R|^2>), averaged over the frames before and
  // after it and its neighbouring bins. Where one source's direct sound
  // dominates, c is near 1; where reflections, the diffuse tail or several
  // sources mix, it falls, and so does the vote. floor 0: no selection.
  // Off by default (alone it moved the rooms' figures by a few points);
  // part of reverberant() below, where with onset weighting and every bin
  // voting alike it helps.
  double coherence_floor = 0;
  double coherence_exponent = 1;
  // Onset (precedence) weighting: a bin votes with the weight
  // max(0, 1 - R / P)^onset_exponent, P its power in this frame and R the
  // loudest power it had in the frames before, each lowered by
  // onset_decay_db per frame since (the fastest a reverberant tail could
  // have decayed from there). Where a sound starts or rises, its direct
  // sound leads its reflections and the tail, and its interaural cues are
  // those of its direction (the precedence effect: Wallach, Newman and
  // Rosenzweig 1949; Zurek 1987; as onset-weighted cues, Martin 1997 and
  // Woodruff and Wang 2012); where it holds or falls, what reaches the ears
  // is more and more the room. A bin after a silent frame rises from
  // silence (weight 1); the block's first frame, with nothing before it,
  // votes with onset_first_frame_weight. 0: no onset weighting.
  double onset_exponent = 0;
  double onset_decay_db = 3;
  double onset_first_frame_weight = 0.5;
  // Blocks pooled across head turns (localise(blocks)) weigh a direction
  // by the geometric mean of what each block's votes give it rather than by
  // their sum (AzimuthVotes::separateSources, jointly): a source is heard
  // at its direction in every block, its mirror image in one block only.
  // In rooms it keeps two blocks' mirror images (or one block's mirror
  // image and another talker's votes) from outweighing the true direction:
  // part of reverberant(). Off by default: in the free field the sum does
  // as well, and where the two blocks' peaks lie a few degrees apart (a
  // template's per-bin phase against a pure delay) the geometric mean's
  // peak falls between them less well than the sum's.
  bool joint_blocks = false;
  int max_peaks = 4;
  double min_peak_separation_deg = 20;
  double min_peak_relative_weight = 0.1;  // of what the first peak explained

  // For a reverberant place (a scenario with <acoustics>, a building): the
  // defaults with onset weighting (exponent 2), interaural-coherence
  // selection (floor 0.3), blocks pooled jointly and every bin voting alike
  // (weight_exponent 0: weighed by amplitude, the loudest talker's bins
  // and the tail it leaves hold most of the weight; counted alike, each
  // talker's glimpses count). In the rooms of ./beft bench hearing (T60
  // 0.6 s, one head turn, one 0.1 s block at each pose) it lifts two talkers within 5 degrees from 0.72
  // to 0.88 and three from 0.52 to 0.69. It is not the default: in the
  // free field it costs what the defaults are tuned for, a steady or
  // narrow-band sound beside another (onsets are a talker's, not an
  // engine's; counting bins favours the broadband sound): two different
  // sounds within 10 degrees fall from 0.91 to about 0.81. Chosen by the
  // place, not estimated from the block: blending it in by the block's
  // mean interaural coherence did worse in the rooms than either profile.
  static LocaliserConfig reverberant();
};

struct LocalisedPeak {
  double azimuth_deg = 0;  // head-relative, CCW, 0 = front
  double weight = 0;       // share of the block's votes it explains
  BandSignature signature;  // energy per band of the votes it explains
};

struct BlockLocalisation {
  AzimuthPosterior posterior;       // flat when silent
  // The sources told apart in the votes (azimuth_votes.hpp), strongest
  // first; none when silent. Each is still front-back ambiguous: the
  // posterior holds its mirror image too (pool blocks across a head turn,
  // localise(blocks), to tell them apart).
  std::vector<LocalisedPeak> peaks;
  int voting_frames = 0;
  bool silent() const { return voting_frames == 0; }
};

// One block of ear signals and how far the head has turned since (CCW [deg]).
struct EarBlock {
  const std::vector<float>& left;
  const std::vector<float>& right;
  double turned_since_deg = 0;
};

class BlockLocaliser {
 public:
  explicit BlockLocaliser(InterauralTemplates templates, const LocaliserConfig& config = LocaliserConfig{});

  // `left` and `right` at the templates' sample rate, of equal length (a
  // block is 0.1 s; blocks shorter than a frame are zero-padded to one).
  // Throws std::invalid_argument if the lengths differ or a sample is not finite.
  BlockLocalisation localise(const std::vector<float>& left, const std::vector<float>& right) const;

  // Several blocks heard while the head turned, their votes pooled in the
  // frame of the head now (turned_since_deg 0). A source's true direction
  // agrees across the blocks while its front-back mirror image moves by twice
  // the turn, so the peaks are on the side the turn showed. Throws as above.
  BlockLocalisation localise(const std::vector<EarBlock>& blocks) const;

  const LocaliserConfig& config() const { return config_; }
  const InterauralTemplates& templates() const { return templates_; }

 private:
  struct FrameSpectra;
  static void interauralCoherence(std::vector<FrameSpectra>& frames);
  void onsetWeights(std::vector<FrameSpectra>& frames) const;

  void addVotes(const std::vector<float>& left, const std::vector<float>& right, int shift, AzimuthVotes& votes,
                int& voting_frames) const;
  std::vector<FrameSpectra> loudFrameSpectra(const std::vector<float>& left, const std::vector<float>& right) const;
  double votingThreshold(const std::vector<FrameSpectra>& frames) const;
  void addPhaseVotes(const FrameSpectra& frame, int band, int shift, AzimuthVotes& votes) const;
  void addLevelVote(const FrameSpectra& frame, int band, int shift, AzimuthVotes& votes) const;

  InterauralTemplates templates_;
  LocaliserConfig config_;
  RealFft fft_;
  std::vector<float> window_;
  double window_power_ = 0;  // sum of the squared window
};

}  // namespace beft::hearing
