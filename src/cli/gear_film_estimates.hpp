// `tehl gear`: the films of the published isothermal fits at the points A .. E of the path.
#pragma once

#include <iosfwd>

#include "scene/film_case.hpp"
#include "scene/gear_case.hpp"

namespace tehl::cli {

// Rq of the [surfaces] waviness when roughness is on: a sinusoid of amplitude A has Rq =
// A / sqrt(2); the two surfaces combine as sqrt(Rq1^2 + Rq2^2) [m]. 0 without waviness.
double CompositeWavinessRq(const internal::Document& doc);

// Appends the section: at A, B, C, D and E (B and D on their single-contact side) R, um, w,
// p_H and Pan & Hamrock's central and minimum film and Moes' central film, from the inlet
// viscosity and its pressure coefficient; with rq_m > 0 also lambda = h_min / Rq.
void FilmEstimates(std::ostream& o,
                   const internal::GearCase& c,
                   const internal::FilmCase& film,
                   double rq_m);

}  // namespace tehl::cli
