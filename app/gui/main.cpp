#include <QApplication>
#include <QMainWindow>

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  QMainWindow window;
  window.setWindowTitle(QObject::tr("Tactile Workbench"));
  window.show();
  return app.exec();
}
