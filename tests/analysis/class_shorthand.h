// One-letter names of the contact classes for confusion tables written out by hand in tests.
#pragma once

#include "run/contact_class.h"

namespace tactile::analysis::shorthand {

inline constexpr ContactClass W = ContactClass::Wall;
inline constexpr ContactClass C = ContactClass::Corner;
inline constexpr ContactClass L = ContactClass::LeavingWall;

}  // namespace tactile::analysis::shorthand
