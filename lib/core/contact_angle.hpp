// Liquid–solid contact angle θ. Stored in radians (SI inside); built only from an explicit
// Radians{} or Degrees{} so a bare number in the wrong unit cannot reach the physics
// (θ = 40 read as radians makes Mikami's exp(B) overflow: docs/model.md).
#pragma once

#include <numbers>

namespace demscale {

struct Radians { double value; };
struct Degrees { double value; };

class ContactAngle {
public:
    // Accepted range [0, π/2): a wetting liquid forming a concave pendular bridge.
    explicit ContactAngle(Radians r);
    explicit ContactAngle(Degrees d);

    double radians() const { return rad_; }
    double degrees() const { return rad_ * 180.0 / std::numbers::pi; }

private:
    double rad_;
};

}  // namespace demscale
