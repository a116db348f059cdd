// The paper's model, equation by equation (../shared/spec/model.md): geometry,
// degradation (eqs. 1-2), labelling (eq. 3) and dynamic-weighting curves
// (eq. 4). Plain functions, no LCM, no state.
#pragma once

#include <string>
#include <vector>

#include "lib/common/declared_parameters.hpp"

#include <string>
#include <vector>

namespace beft::model {

// Named parameters; the defaults are the readings of spec/model.md, the
// paper's literal formulas are one setting away.
enum class LabelForm { Default, Printed };

struct Parameters {
  double aw_variance_deg2 = 8100;  // s in a_w; the printed value is 90
  double label_gain = 20;          // g in eq. 3 (Default form)
  LabelForm label_form = LabelForm::Default;
  int t_max = 10;                  // T_max of eq. 4 [DW steps]
  double n = 100;                  // n of eq. 4 (T_max^2: one curve spans 0.25)
};

// ---- Geometry (low-level experts) ----

// Angle wrapped into (-180, 180] degrees.
double wrapDegrees(double angle_deg);

// d_i: 3-D distance from the platform centre to a point [m].
double distance(double px, double py, double pz, double ox, double oy, double oz);

// alpha_i: azimuth of (ox, oy) seen from (px, py) relative to the nose heading
// (platform yaw + head yaw) in degrees, in (-180, 180], positive to the left.
double azimuth(double px, double py, double nose_heading_deg, double ox, double oy);

// ---- Degradation, eqs. 1-2 ----

// g_d(d) = 1 - 1 / (1 + exp(-(d - 10) / 2)); v_d = a_d = g_d.
double distanceDegradation(double d);
// a_w(alpha) = exp(-0.5 alpha^2 / s), alpha in degrees.
double azimuthDegradation(double alpha_deg, const Parameters& p = {});
// v_o(O_v) = 1 - O_v / 100, O_v in percent.
double visualOcclusionDegradation(double occlusion_pct);
// a_o(O_a) = 1 - 0.8 O_a / 100, O_a in percent (>= 0.2).
double acousticOcclusionDegradation(double occlusion_pct);
// Eq. 1: v_P = v_d(d) * v_o(O_v).
double visualPerceptibility(double d, double occlusion_pct);
// Eq. 2: a_P = a_d(d) * a_o(O_a) * a_w(alpha).
double acousticPerceptibility(double d, double occlusion_pct, double alpha_deg,
                              const Parameters& p = {});

// ---- Labelling, eq. 3 ----

// L_j for one category: is_true_category says whether the object's label is k_j.
double labelConfidence(bool is_true_category, double perceptibility, const Parameters& p = {});
// L_j for every category, in the order given.
std::vector<double> labelConfidences(const std::vector<std::string>& categories,
                                     const std::string& true_label, double perceptibility,
                                     const Parameters& p = {});
// The same into out (its storage reused).
void labelConfidences(const std::vector<std::string>& categories, const std::string& true_label,
                      double perceptibility, const Parameters& p, std::vector<double>& out);

// ---- Dynamic weighting, eq. 4 ----

// Rising curve: log(min(t, T_max)) / (2 log n) + c, t >= 1, clamped to [0, 1].
double weightRising(int t, double c, const Parameters& p = {});
// Falling curve: 2c - (log(min(t, T_max)) / (2 log n) + c), clamped to [0, 1].
double weightFalling(int t, double c, const Parameters& p = {});

// Declares the parameters named (all when none are) as members of p, for the
// experts that use them: aw_variance_deg2, label_gain, label_form, t_max, n.
void declareParameters(DeclaredParameters& declared, Parameters& p, const std::vector<std::string>& names = {});
// Sets one parameter by name through those declarations; throws
// std::invalid_argument naming the parameter and its range.
void setParameter(Parameters& p, const std::string& name, const std::string& value);

}  // namespace beft::model
