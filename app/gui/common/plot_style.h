// Colours and names shared by every view: the blue-to-red value scale of the sensor heatmap and
// the robot's domes, one colour per contact class, the heading quadrant colours and the command
// lanes (thesis section 4.1 layout).
#pragma once

#include <QColor>
#include <QString>

#include "run/contact_class.h"

namespace tactile::gui {

// Sensor values map 0..kMaxNormal to blue..red (values outside are clamped).
QColor valueColor(double value, double maxValue);
// One fixed colour per class (NoContact light grey).
QColor classColor(ContactClass cls);
// Display name of a class (translated).
QString className(ContactClass cls);
// Heading colour: blue when the heading points into the first or fourth quadrant (cos >= 0), red
// in the second and third.
QColor headingColor(double theta);

}  // namespace tactile::gui
