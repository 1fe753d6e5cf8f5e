// placeholder: replaced by the real tests
#include <QtTest>
class Placeholder : public QObject {
  Q_OBJECT
};
QTEST_MAIN(Placeholder)
#include "prediction_test.moc"
