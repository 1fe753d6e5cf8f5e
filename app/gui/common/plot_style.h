// Colours and names shared by every view: the value scales of the sensor heatmap, the robot's
// domes and the signal bars, one colour per contact class, the heading quadrant colours and the
// command lanes (thesis section 4.1 layout).
#pragma once

#include <QColor>
#include <QString>

#include "run/contact_class.h"

namespace tactile::gui {

// A quantity that only grows (normal force, magnitude): 0..maxValue on a perceptually uniform
// sequential scale (viridis: dark purple to yellow, lightness rising monotonically, readable in
// greyscale and to colour-blind readers). Values outside are clamped.
QColor valueColor(double value, double maxValue);
// A signed quantity (shear): -maxAbs..maxAbs on a diverging scale, blue below zero, a light neutral
// grey at zero, red above; equal magnitudes are equally light. Values outside are clamped.
QColor signedValueColor(double value, double maxAbs);
// One fixed colour per class (NoContact light grey).
QColor classColor(ContactClass cls);
// Display name of a class (translated).
QString className(ContactClass cls);
// Heading colour: blue when the heading points into the first or fourth quadrant (cos >= 0), red
// in the second and third.
QColor headingColor(double theta);

}  // namespace tactile::gui
