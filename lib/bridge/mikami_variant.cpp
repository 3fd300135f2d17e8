#include "bridge/mikami_variant.hpp"

#include "core/input_error.hpp"

namespace demscale::bridge {

std::string_view to_string(MikamiVariant v) {
    return v == MikamiVariant::mikami1998 ? "mikami1998" : "yun-park-2017";
}

std::string_view to_string(RuptureLaw r) {
    switch (r) {
        case RuptureLaw::mikami1998: return "mikami1998";
        case RuptureLaw::lian1993: return "lian1993";
        case RuptureLaw::willett2000: return "willett2000";
    }
    return "?";
}

std::string_view to_string(BridgeGeometry g) {
    return g == BridgeGeometry::sphere_sphere ? "sphere-sphere" : "sphere-wall";
}

MikamiVariant parse_mikami_variant(std::string_view text, const std::string& field) {
    if (text == "mikami1998") return MikamiVariant::mikami1998;
    if (text == "yun-park-2017") return MikamiVariant::yun_park_2017;
    throw InputError(field, "\"" + std::string(text) + "\"", "one of mikami1998, yun-park-2017");
}

RuptureLaw parse_rupture_law(std::string_view text, const std::string& field) {
    if (text == "mikami1998") return RuptureLaw::mikami1998;
    if (text == "lian1993") return RuptureLaw::lian1993;
    if (text == "willett2000") return RuptureLaw::willett2000;
    throw InputError(field, "\"" + std::string(text) + "\"", "one of mikami1998, lian1993, willett2000");
}

}  // namespace demscale::bridge
