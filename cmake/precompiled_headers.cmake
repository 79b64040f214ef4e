# Precompiled headers: the third-party headers nearly every file of a layer includes (Eigen and
# the standard library in core; Qt Core and Serial Bus in devices; Qt Widgets in the GUI; Qt
# Test in the GUI tests). Parsing them was most of each file's compile time: measured on this
# machine (g++ 12, -O2 -g1), dh_chain.cpp 3.75 -> 1.60 s, dro_panel.cpp 5.10 -> 2.74 s,
# main_window.cpp 11.2 -> 6.6 s, test_operator_defects.cpp 14.7 -> 7.4 s. Each file still
# includes what it uses (the build without them, -DCUTCELL_PCH=OFF, must keep compiling).
option(CUTCELL_PCH "Precompile the common third-party headers of each layer" ON)

set(CUTCELL_PCH_STD <algorithm> <array> <cmath> <functional> <map> <memory> <optional>
                    <stdexcept> <string> <vector>)
set(CUTCELL_PCH_core <Eigen/Core> <Eigen/Geometry> ${CUTCELL_PCH_STD})
set(CUTCELL_PCH_qtcore ${CUTCELL_PCH_core} <QObject> <QString> <QStringList> <QThread> <QTimer>
                       <QCanBusDevice> <QCanBusFrame>)
set(CUTCELL_PCH_widgets ${CUTCELL_PCH_core} <QObject> <QString> <QStringList> <QTimer> <QLocale>
    <QWidget> <QLabel> <QPushButton> <QBoxLayout> <QGridLayout> <QFormLayout> <QGroupBox>
    <QSpinBox> <QComboBox> <QCheckBox> <QLineEdit> <QTableWidget> <QHeaderView> <QTabWidget>
    <QScrollArea> <QAction> <QMenu> <QMessageBox>)
set(CUTCELL_PCH_gtest ${CUTCELL_PCH_core} <gtest/gtest.h>)
set(CUTCELL_PCH_qttest ${CUTCELL_PCH_widgets} <QtTest> <QSignalSpy> <QTemporaryDir>)

# cutcell_precompile(<target> core|qtcore|widgets|qttest)
function(cutcell_precompile target kind)
  if(CUTCELL_PCH)
    target_precompile_headers(${target} PRIVATE ${CUTCELL_PCH_${kind}})
  endif()
endfunction()

# cutcell_precompile_reuse(<target> <from>): the GUI tests share one precompiled header (one
# file each: a header of their own would cost more than it saves). Same flags as <from>.
function(cutcell_precompile_reuse target from)
  if(CUTCELL_PCH)
    target_precompile_headers(${target} REUSE_FROM ${from})
  endif()
endfunction()
