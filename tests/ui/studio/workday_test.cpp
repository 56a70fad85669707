// The studio over a working day (run under xvfb-run): settings applied to the current shape or
// asked about, a modified session saved before closing (a name without extension gets .json),
// Frame all and a picture of the whole deformed sheet, one export dialog, a recording whose files
// are numbered consecutively and exist while it runs, a scenario corner dragged like a handle,
// undo entries that name their edit, the chart's marks and "done", the wireframe's default by
// mesh size, and the shortcuts and mouse actions listed in Help and in the docs.
#include <QVTKOpenGLNativeWidget.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <memory>

#include "app/blas_kernels.h"
#include "ui/studio/click_drag_style.h"
#include "ui/studio/export_dialog.h"
#include "ui/studio/main_window.h"
#include "ui/studio/objective_chart.h"
#include "ui/studio/screen_picking.h"
#include "ui/studio/solver_panel.h"
#include "ui/studio/solver_settings.h"

using sdog::studio::MainWindow;
namespace vis = sdog::vis;

namespace {

const QString kPattern = QString(SDOG_DATASETS_DIR) + "/four_corner_arcs.svg";
constexpr int kWait = 120000;  // ms: the machine may be busy

/// Whether a pixel is the view's white background.
bool background(QRgb p) {
  return qRed(p) >= 250 && qGreen(p) >= 250 && qBlue(p) >= 250;
}

/// The largest share of the drawing area's width or height (the view left of the legend column)
/// that the projected points span, and whether all of them lie inside the view.
struct Framing {
  double fill = 0;
  bool inside = true;
};
Framing framing_of(vtkRenderer* renderer, const std::vector<Eigen::Vector3d>& points) {
  const int* size = renderer->GetSize();
  double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
  Framing f;
  for (const auto& p : points) {
    const Eigen::Vector3d d = sdog::studio::to_display(renderer, p);
    lo_x = std::min(lo_x, d.x()), hi_x = std::max(hi_x, d.x());
    lo_y = std::min(lo_y, d.y()), hi_y = std::max(hi_y, d.y());
    if (d.x() < 0 || d.y() < 0 || d.x() > size[0] || d.y() > size[1]) f.inside = false;
  }
  f.fill = std::max((hi_x - lo_x) / (0.75 * size[0]), (hi_y - lo_y) / size[1]);
  return f;
}

}  // namespace

class WorkdayTest : public QObject {
  Q_OBJECT

  std::unique_ptr<MainWindow> window_;
  QStringList errors_, questions_;
  int answer_ = -1;  // the answer the question sink gives (-1: the last, cancelling one)
  QString save_path_;

  void open(const QString& resolution = "21x21") {
    QVERIFY(window_->open_pattern(kPattern, resolution));
    QTRY_VERIFY_WITH_TIMEOUT(window_->snapshot() != nullptr, kWait);
  }
  int iteration() const { return window_->snapshot() ? window_->snapshot()->iteration : -1; }
  void steps(int n) {
    const int target = iteration() + n;
    window_->step(n);
    QTRY_COMPARE_WITH_TIMEOUT(iteration(), target, kWait);
  }
  std::unique_ptr<MainWindow> new_window() {
    auto w = std::make_unique<MainWindow>("about");
    w->set_error_sink([this](const QString& m) { errors_ << m; });
    w->set_question_sink([this](const QString& q, const QStringList& answers) {
      questions_ << q;
      return answer_ >= 0 ? answer_ : static_cast<int>(answers.size()) - 1;
    });
    w->set_save_path_sink([this](const QString&, const QString&) { return save_path_; });
    w->resize(900, 600);
    w->show();
    return w;
  }

 private Q_SLOTS:
  void init() {
    errors_.clear();
    questions_.clear();
    answer_ = -1;
    save_path_.clear();
    window_ = new_window();
  }
  void cleanup() { window_.reset(); }

  // Apply in the Solver panel asks once the session has left its start state: keep the shape
  // (the iteration and positions stay, the new weight acts on them), start again, or cancel.
  void applies_settings_to_the_shape_or_asks() {
    open();
    auto* panel = window_->solver_panel();
    auto* isometry = qobject_cast<QDoubleSpinBox*>(panel->form()->field("isometry weight"));
    QVERIFY(isometry);
    // At the start state nothing is lost: no question.
    isometry->setValue(15000);
    QTest::mouseClick(panel->apply_button(), Qt::LeftButton);
    QCOMPARE(questions_.size(), 0);
    QCOMPARE(window_->run_config().weights.isometry, 15000.0);
    steps(3);
    const Eigen::MatrixX3d shape = window_->snapshot()->state.fine;
    answer_ = 0;  // keep the shape
    isometry->setValue(500);
    QTest::mouseClick(panel->apply_button(), Qt::LeftButton);
    QCOMPARE(questions_.size(), 1);
    QVERIFY(questions_[0].contains("iteration 3"));
    QCOMPARE(window_->run_config().weights.isometry, 500.0);
    QTRY_VERIFY_WITH_TIMEOUT(window_->status_text().contains("applied to the shape of iteration 3"),
                             kWait);
    QTest::qWait(300);
    QCOMPARE(iteration(), 3);
    QVERIFY((window_->snapshot()->state.fine - shape).norm() < 1e-12);
    steps(1);  // goes on from there with the new weight
    QCOMPARE(iteration(), 4);
    answer_ = 2;  // cancel: nothing changes
    isometry->setValue(700);
    QTest::mouseClick(panel->apply_button(), Qt::LeftButton);
    QCOMPARE(questions_.size(), 2);
    QCOMPARE(window_->run_config().weights.isometry, 500.0);
    QCOMPARE(isometry->value(), 500.0);  // the panel shows the settings in use again
    QCOMPARE(iteration(), 4);
    // Another scenario cannot keep the shape: it asks, and Cancel keeps everything.
    answer_ = 1;
    QVERIFY(!window_->choose_scenario("fold"));
    QCOMPARE(questions_.size(), 3);
    QVERIFY(questions_[2].contains("Another scenario"));
    QCOMPARE(window_->run_config().scenario, sdog::ScenarioKind::kCorners);
    QCOMPARE(iteration(), 4);
    answer_ = 1;  // start again
    isometry->setValue(800);
    QTest::mouseClick(panel->apply_button(), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(iteration(), 0, kWait);
    QCOMPARE(window_->run_config().weights.isometry, 800.0);
    QVERIFY(errors_.isEmpty());
  }

  // Quit with a modified session asks; Cancel keeps the window; Save asks for a file, a name
  // without extension gets .json, and the workspace reopens. Saved and unchanged: no question.
  void asks_to_save_before_closing() {
    open();
    QVERIFY(!window_->modified());
    QVERIFY(window_->settle_unsaved("closing"));  // nothing to lose: no question
    QCOMPARE(questions_.size(), 0);
    steps(2);
    QVERIFY(window_->modified());
    answer_ = 2;  // cancel
    QVERIFY(!window_->close());
    QCOMPARE(questions_.size(), 1);
    QVERIFY(questions_[0].contains("closing"));
    QVERIFY(window_->isVisible());
    QVERIFY(!window_->settle_unsaved("opening another pattern"));
    QTemporaryDir dir;
    save_path_ = dir.filePath("ws1");
    answer_ = 0;  // save
    QVERIFY(window_->close());
    QVERIFY(QFileInfo(dir.filePath("ws1.json")).size() > 1000);
    QVERIFY(!QFileInfo::exists(dir.filePath("ws1")));
    QVERIFY(window_->status_text().contains(dir.filePath("ws1.json")));
    QVERIFY(!window_->modified());
    auto other = new_window();
    QVERIFY(other->open_workspace(dir.filePath("ws1.json")));
    QTRY_VERIFY_WITH_TIMEOUT(other->snapshot() && other->snapshot()->iteration == 2, kWait);
    // The File menu's save does the same: the extension is added, the status bar names the file.
    other->set_save_path_sink([&](const QString&, const QString&) { return dir.filePath("ws2"); });
    QSignalSpy saved(other.get(), &MainWindow::workspace_saved);
    QVERIFY(other->save_workspace(dir.filePath("ws2")));
    QTRY_COMPARE_WITH_TIMEOUT(saved.count(), 1, kWait);
    QVERIFY(QFileInfo::exists(dir.filePath("ws2.json")));
    QVERIFY(other->status_text().contains("ws2.json"));
    QVERIFY(other->save_camera(dir.filePath("view")));  // View > Save camera too
    QVERIFY(QFileInfo::exists(dir.filePath("view.json")));
    QVERIFY(other->status_text().contains(dir.filePath("view.json")));
    QVERIFY(errors_.isEmpty());
  }

  // View > Frame all: the deformed sheet, zoomed out of view, is put back inside it from the same
  // direction, filling it; the window picture of sdog-studio --screenshot shows the whole sheet.
  void frames_the_deformed_sheet() {
    open();
    steps(40);  // the corners scenario lifts the sheet
    vtkRenderer* renderer = window_->renderer();
    vtkCamera* camera = renderer->GetActiveCamera();
    window_->resize(1400, 900);
    QApplication::processEvents();
    camera->Dolly(3);
    renderer->ResetCameraClippingRange();
    window_->render();
    const std::vector<Eigen::Vector3d> sheet = window_->scene()->drawn_points();
    QVERIFY(!framing_of(renderer, sheet).inside);  // the test can fail: the sheet is cut off
    double before[3];
    camera->GetDirectionOfProjection(before);
    QTemporaryDir dir;
    const QString cut = dir.filePath("cut.png"), whole = dir.filePath("whole.png");
    QVERIFY(window_->save_window_image(cut));
    window_->frame_all();  // View > Frame all
    const Framing f = framing_of(renderer, sheet);
    QVERIFY(f.inside);
    QVERIFY2(f.fill > 0.6, qPrintable(QString::number(f.fill)));
    double after[3];
    camera->GetDirectionOfProjection(after);
    QVERIFY(before[0] * after[0] + before[1] * after[1] + before[2] * after[2] > 0.99999);
    // What sdog-studio --screenshot saves: the window with the sheet framed first.
    camera->Dolly(3);
    renderer->ResetCameraClippingRange();
    QVERIFY(window_->save_window_image(whole, /*frame_sheet=*/true));
    // Keep the sheet framed: every new state is framed as it comes.
    camera->Dolly(3);
    renderer->ResetCameraClippingRange();
    window_->set_keep_framed(true);
    steps(10);
    QVERIFY(framing_of(renderer, window_->scene()->drawn_points()).inside);
    window_->set_keep_framed(false);
    // In the picture, the sheet touches no edge of the view's drawing area.
    const QRect view = window_->centralWidget()->geometry();
    auto touches_edge = [&](const QImage& image) {
      int sheet = 0, edge = 0;
      for (int y = view.top() + 2; y <= view.bottom() - 2; ++y)
        for (int x = view.left() + 2; x < view.left() + int(0.72 * view.width()); ++x) {
          if (background(image.pixel(x, y))) continue;
          ++sheet;
          if (x <= view.left() + 3 || y <= view.top() + 3 || y >= view.bottom() - 3) ++edge;
        }
      return std::pair{sheet, edge};
    };
    const auto [cut_sheet, cut_edge] = touches_edge(QImage(cut));
    const auto [sheet_pixels, edge_pixels] = touches_edge(QImage(whole));
    QVERIFY(cut_edge > 0);
    QVERIFY(sheet_pixels > view.width() * view.height() / 10);
    QCOMPARE(edge_pixels, 0);
    QVERIFY(errors_.isEmpty());
  }

  // File > Export screenshot: one dialog (file, size, background, framing); a name without
  // extension gets .png; framing fills the picture from the view's direction.
  void exports_with_one_dialog() {
    open();
    steps(20);
    window_->renderer()->GetActiveCamera()->Dolly(0.3);  // the sheet small in the view
    window_->renderer()->ResetCameraClippingRange();
    window_->render();
    QTemporaryDir dir;
    sdog::studio::ExportDialog dialog(dir.filePath("shot"), {1600, 900});
    dialog.width_field()->setValue(640);
    dialog.height_field()->setValue(400);
    dialog.transparent_field()->setChecked(true);
    QVERIFY(dialog.frame());  // the default
    QCOMPARE(dialog.size().width, 640);
    QCOMPARE(dialog.size().height, 400);
    QVERIFY(dialog.transparent());
    QVERIFY(window_->export_screenshot(dialog.path(), dialog.size(), dialog.transparent(),
                                       dialog.frame()));
    const QImage framed(dir.filePath("shot.png"));
    QCOMPARE(framed.size(), QSize(640, 400));
    QVERIFY(window_->status_text().contains(dir.filePath("shot.png")));
    dialog.framing_field()->setCurrentIndex(1);
    QVERIFY(!dialog.frame());
    QVERIFY(
        window_->export_screenshot(dir.filePath("as_is.png"), dialog.size(), true, dialog.frame()));
    // The sheet's extent in each picture (opaque pixels left of the legend column).
    auto extent = [](const QImage& image) {
      int lo_x = image.width(), hi_x = -1, lo_y = image.height(), hi_y = -1;
      for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < int(0.72 * image.width()); ++x)
          if (qAlpha(image.pixel(x, y)) > 0) {
            lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x), lo_y = std::min(lo_y, y),
            hi_y = std::max(hi_y, y);
          }
      return std::max((hi_x - lo_x) / (0.75 * image.width()),
                      (hi_y - lo_y) / double(image.height()));
    };
    const double filled = extent(framed), small = extent(QImage(dir.filePath("as_is.png")));
    QVERIFY2(filled > 0.75, qPrintable(QString::number(filled)));
    QVERIFY2(small < 0.5 * filled, qPrintable(QString("%1 %2").arg(small).arg(filled)));
    QVERIFY(errors_.isEmpty());
  }

  // File > Record frames while playing for 10 s: the files are there while it runs, numbered from
  // frame_0000 without gaps, frames.csv lists one row per frame (the iterations in order), the
  // indicator shows the count; a folder holding a recording is refused; every 3rd iteration.
  void records_while_playing() {
    open();
    QTemporaryDir dir;
    const QString frames = dir.filePath("frames");
    sdog::control::RecordingOptions options;
    options.png = options.vtu = options.surface = true;
    QVERIFY(window_->start_frames(frames, options));
    QCOMPARE(window_->frames_recorded(), 1);  // the state shown
    QElapsedTimer clock;
    clock.start();
    window_->play();
    auto check_files = [&](const QString& when, int n) {
      for (int k = 0; k < n; ++k)
        for (const QString& name :
             {QString("frame_%1.png"), QString("frame_%1.vtu"), QString("surface_%1.vtp")}) {
          const QString file = frames + "/" + name.arg(k, 4, 10, QChar('0'));
          QVERIFY2(QFileInfo(file).size() > 100, qPrintable(when + ": " + file));
        }
      QVERIFY2(!QFileInfo::exists(frames + QString("/frame_%1.png").arg(n, 4, 10, QChar('0'))),
               qPrintable(when));
      QFile csv(frames + "/frames.csv");
      QVERIFY(csv.open(QIODevice::ReadOnly));
      const QStringList rows = QString::fromUtf8(csv.readAll()).split('\n', Qt::SkipEmptyParts);
      QCOMPARE(rows.size(), n + 1);
      int last = -1;
      for (int k = 1; k < rows.size(); ++k) {
        const QStringList cells = rows[k].split(',');
        QCOMPARE(cells[0].toInt(), k - 1);
        QVERIFY2(cells[1].toInt() == last + 1, qPrintable(rows[k]));  // every iteration, in order
        last = cells[1].toInt();
      }
      QVERIFY(QDir(frames).entryList({"*.tmp*", ".*"}, QDir::Files | QDir::Hidden).isEmpty());
    };
    QTRY_VERIFY_WITH_TIMEOUT(window_->frames_recorded() >= 4, kWait);
    check_files("while recording", window_->frames_recorded());
    QVERIFY2(window_->recording_indicator().contains("REC"),
             qPrintable(window_->recording_indicator()));
    QVERIFY(window_->recording_indicator().contains(QString::number(window_->frames_recorded())));
    while (clock.elapsed() < 10000 && window_->playing()) QTest::qWait(100);
    window_->pause();
    QTRY_VERIFY_WITH_TIMEOUT(!window_->playing(), kWait);
    QTest::qWait(200);
    QSignalSpy written(window_.get(), &MainWindow::frames_written);
    const int n = window_->frames_recorded();
    window_->stop_frames();
    QCOMPARE(written.count(), 1);
    QCOMPARE(written[0][1].toInt(), n);
    QVERIFY(window_->recording_indicator().isEmpty());
    QVERIFY(window_->status_text().contains(QString("%1 frames").arg(n)));
    check_files("after recording", n);
    QVERIFY2(n > 10, qPrintable(QString::number(n)));
    QVERIFY(QFileInfo(frames + "/frames.pvd").size() > 100);
    QVERIFY(QFileInfo(frames + "/surface.pvd").size() > 100);
    QVERIFY(errors_.isEmpty());
    // The same folder again: refused, nothing changed.
    QVERIFY(!window_->start_frames(frames, options));
    QCOMPARE(errors_.size(), 1);
    QVERIFY(errors_[0].contains("already holds a recording"));
    // Every 3rd iteration, pictures only.
    sdog::control::RecordingOptions sparse;
    sparse.every = 3;
    const QString every3 = dir.filePath("every3");
    const int start = iteration();
    QVERIFY(window_->start_frames(every3, sparse));
    steps(7);
    window_->stop_frames();
    QFile csv(every3 + "/frames.csv");
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList rows = QString::fromUtf8(csv.readAll()).split('\n', Qt::SkipEmptyParts);
    QStringList iterations;
    for (int k = 1; k < rows.size(); ++k) iterations << rows[k].split(',')[1];
    QStringList expected{QString::number(start)};
    for (int i = start + 1; i <= start + 7; ++i)
      if (i % 3 == 0) expected << QString::number(i);
    QCOMPARE(iterations, expected);
    QCOMPARE(QDir(every3).entryList({"*.png"}).size(), expected.size());
    QVERIFY(QDir(every3).entryList({"*.vtu"}).isEmpty());
  }

  // A corner of the corners scenario, drawn as a handle, is dragged like one: Shift + drag moves
  // it, it becomes a handle (one undoable edit with the drag), and the sheet follows.
  void drags_a_scenario_corner() {
    open();
    window_->set_layer(vis::Layer::kHandles, true);
    steps(3);
    window_->reset_camera();
    QVERIFY(window_->snapshot()->constraints.handles.empty());
    const auto& drawn = window_->snapshot()->state.constraints.handles;
    QVERIFY(drawn.size() >= 2);
    const int vertex = drawn[0].vertex;
    const Eigen::Vector3d at = sdog::studio::to_display(window_->renderer(), drawn[0].target);
    const Eigen::Vector3d to = at + Eigen::Vector3d(-30, 40, 0);
    vtkRenderWindowInteractor* mouse = window_->interactor();
    auto event = [&](const Eigen::Vector3d& p, unsigned long what) {
      mouse->SetEventInformation(int(std::lround(p.x())), int(std::lround(p.y())), 0, 1);
      mouse->InvokeEvent(what);
    };
    double camera_before[3];
    window_->renderer()->GetActiveCamera()->GetPosition(camera_before);
    event(at, vtkCommand::LeftButtonPressEvent);
    event(to, vtkCommand::MouseMoveEvent);
    event(to, vtkCommand::LeftButtonReleaseEvent);
    double camera_after[3];
    window_->renderer()->GetActiveCamera()->GetPosition(camera_after);
    QCOMPARE(camera_after[0], camera_before[0]);  // the drag did not pan
    QTRY_VERIFY_WITH_TIMEOUT(
        window_->snapshot()->constraints.handles.size() == 1 &&
            (window_->snapshot()->constraints.handles[0].target - drawn[0].target).norm() > 0.1,
        kWait);
    const auto& handle = window_->snapshot()->constraints.handles[0];
    QCOMPARE(handle.vertex, vertex);
    const Eigen::Vector3d dropped = sdog::studio::to_display(window_->renderer(), handle.target);
    QVERIFY2((dropped.head<2>() - to.head<2>()).norm() < 1.5,
             qPrintable(QString("%1 %2").arg(dropped.x()).arg(dropped.y())));
    // Still one target per corner.
    int on_vertex = 0;
    for (const auto& h : window_->snapshot()->state.constraints.handles)
      on_vertex += h.vertex == vertex;
    QCOMPARE(on_vertex, 1);
    steps(5);
    const Eigen::Vector3d moved = window_->snapshot()->state.fine.row(vertex).transpose();
    QVERIFY((moved - handle.target).norm() < (drawn[0].target - handle.target).norm());
    QVERIFY(window_->snapshot()->undo_name.find("scenario's target") != std::string::npos);
    window_->undo();  // the take-over and the drag at once
    QTRY_VERIFY_WITH_TIMEOUT(window_->snapshot()->constraints.handles.empty(), kWait);
    QVERIFY(errors_.isEmpty());
  }

  // Undo and Redo say what they undo; the chart marks a mode switch, the scenario's end and
  // "done", when the solver stops by itself and says so.
  void names_edits_and_marks_the_chart() {
    open();
    window_->add_handles({0, 1});
    QTRY_VERIFY_WITH_TIMEOUT(window_->snapshot()->can_undo, kWait);
    QAction* undo = nullptr;
    QAction* redo = nullptr;
    for (QAction* a : window_->findChildren<QAction*>()) {
      if (a->shortcut() == QKeySequence::Undo) undo = a;
      if (a->shortcut() == QKeySequence("Ctrl+Shift+Z")) redo = a;
    }
    QVERIFY(undo && redo);
    QCOMPARE(undo->text(), QString("&Undo make 2 handles"));
    window_->undo();
    QTRY_VERIFY_WITH_TIMEOUT(!window_->snapshot()->can_undo, kWait);
    QCOMPARE(undo->text(), QString("&Undo"));
    QCOMPARE(redo->text(), QString("&Redo make 2 handles"));

    sdog::RunConfig short_run = window_->run_config();
    short_run.iterations = 6;
    short_run.hold = 2;
    QVERIFY(window_->set_run_config(short_run));
    QTRY_COMPARE_WITH_TIMEOUT(iteration(), 0, kWait);
    steps(2);
    QVERIFY(window_->set_mode("vsadmm"));
    QTRY_VERIFY_WITH_TIMEOUT(window_->snapshot()->mode == "vsadmm", kWait);
    QVERIFY(window_->set_mode("standard"));
    window_->play();
    QTRY_VERIFY_WITH_TIMEOUT(window_->status_text().contains("done"), kWait);
    QTRY_VERIFY_WITH_TIMEOUT(!window_->playing(), kWait);
    QStringList marks;
    for (const auto& m : window_->chart()->marks())
      marks << QString("%1 %2").arg(m.iteration).arg(m.label);
    QVERIFY2(marks.contains("2 mode vsadmm"), qPrintable(marks.join("; ")));
    QVERIFY2(marks.filter("mode standard").size() == 1, qPrintable(marks.join("; ")));
    QVERIFY2(marks.contains("6 scenario end"), qPrintable(marks.join("; ")));
    QVERIFY2(marks.last().endsWith("done"), qPrintable(marks.join("; ")));
    QVERIFY(iteration() >= 6);
    QVERIFY(errors_.isEmpty());
  }

  // The wireframe is on for small meshes and off from 61 grid lines on, unless the user set it.
  void wireframe_default_follows_the_mesh_size() {
    open("21x21");
    QVERIFY(window_->layer_action(vis::Layer::kWireframe)->isChecked());
    QVERIFY(window_->scene()->layer_on(vis::Layer::kWireframe));
    QVERIFY(window_->change_resolution("81x81"));
    QTRY_VERIFY_WITH_TIMEOUT(window_->snapshot() != nullptr, kWait);
    QVERIFY(!window_->layer_action(vis::Layer::kWireframe)->isChecked());
    QVERIFY(!window_->scene()->layer_on(vis::Layer::kWireframe));
    QVERIFY(window_->change_resolution("21x21"));
    QVERIFY(window_->scene()->layer_on(vis::Layer::kWireframe));
    window_->set_layer(vis::Layer::kWireframe, false);  // the user's choice stays
    QVERIFY(window_->change_resolution("41x41"));
    QVERIFY(!window_->scene()->layer_on(vis::Layer::kWireframe));
    QVERIFY(errors_.isEmpty());
  }

  // Help > Keyboard shortcuts lists every shortcut and mouse action, and so do the README and
  // docs/reference/studio.md.
  void lists_shortcuts_and_mouse_actions() {
    const QString help = window_->keyboard_shortcuts();
    int shortcuts = 0;
    for (const QAction* a : window_->findChildren<QAction*>())
      for (const QKeySequence& key : a->shortcuts()) {
        ++shortcuts;
        QVERIFY2(
            help.contains("<b>" + key.toString(QKeySequence::NativeText).toHtmlEscaped() + "</b>"),
            qPrintable(key.toString() + " of " + a->text()));
      }
    QVERIFY(shortcuts > 25);
    for (const QString& name : {QString(SDOG_DOCS_DIR) + "/reference/studio.md",
                                QString(SDOG_DOCS_DIR) + "/../README.md"}) {
      QFile file(name);
      QVERIFY(file.open(QIODevice::ReadOnly));
      const QString page = QString::fromUtf8(file.readAll());
      for (const auto& [action, effect] : sdog::studio::mouse_actions()) {
        QVERIFY2(help.contains(QString(action).toHtmlEscaped()), action);
        QVERIFY2(page.contains(QString("| %1 |").arg(action)),
                 qPrintable(name + " lacks the mouse action " + action));
      }
      for (const QAction* a : window_->findChildren<QAction*>())
        for (const QKeySequence& key : a->shortcuts()) {
          const QString text = key.toString(QKeySequence::PortableText);
          QVERIFY2(page.contains("`" + text + "`"),
                   qPrintable(name + " lacks the shortcut " + text + " of " + a->text()));
        }
    }
  }
};

int main(int argc, char** argv) {
  sdog::use_avx2_blas_kernels(argv);
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  WorkdayTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "workday_test.moc"
