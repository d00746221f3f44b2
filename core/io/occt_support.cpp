// OpenCASCADE support shared by the STEP export and the STEP/IGES import (occt_support.hpp).
#include "core/io/occt_support.hpp"

#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Controller.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <UnitsMethods.hxx>

namespace pw {
inline namespace io {
namespace occt {

std::unique_lock<std::mutex> lock() {
    static std::mutex m;
    std::unique_lock<std::mutex> held(m);
    static const bool once = [] {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
        STEPControl_Controller::Init();  // the STEP settings (write.step.schema) exist from here on
        return true;
    }();
    (void)once;
    return held;
}

Handle(Geom_BSplineSurface) bezierSurface(const std::array<Vec3, 16>& net, const Weights16* weights) {
    TColgp_Array2OfPnt poles(1, 4, 1, 4);
    TColStd_Array2OfReal w(1, 4, 1, 4);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const Vec3& p = net[size_t(i * 4 + j)];
            poles.SetValue(j + 1, i + 1, gp_Pnt(p.x, p.y, p.z));
            w.SetValue(j + 1, i + 1, weights ? (*weights)[size_t(i * 4 + j)] : 1.0);
        }
    TColStd_Array1OfReal knots(1, 2);
    knots(1) = 0.0;
    knots(2) = 1.0;
    TColStd_Array1OfInteger mults(1, 2);
    mults(1) = 4;
    mults(2) = 4;
    if (weights) return new Geom_BSplineSurface(poles, w, knots, knots, mults, mults, 3, 3);
    return new Geom_BSplineSurface(poles, knots, knots, mults, mults, 3, 3);
}

double useLengthUnit(LengthUnit u) {
    Interface_Static::SetCVal("xstep.cascade.unit", unitName(u));
    const double inMm = metresPer(u) * 1000.0;
    UnitsMethods::SetCasCadeLengthUnit(inMm);
    return inMm;
}

Handle(Geom_BSplineSurface) netBezierSurface(const BezierGrid& g) {
    const int cols = int(g.cols) + (g.closedU ? 1 : 0), rows = int(g.rows) + (g.closedV ? 1 : 0);
    TColgp_Array2OfPnt poles(1, cols, 1, rows);
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < cols; ++j) {
            const Vec3& p = g.points[size_t(i % int(g.rows)) * g.cols + size_t(j % int(g.cols))];
            poles.SetValue(j + 1, i + 1, gp_Pnt(p.x, p.y, p.z));
        }
    auto knots = [](int spans, TColStd_Array1OfReal& k, TColStd_Array1OfInteger& m) {
        for (int i = 0; i <= spans; ++i) {
            k(i + 1) = i;
            m(i + 1) = (i == 0 || i == spans) ? 4 : 3;
        }
    };
    const int su = (cols - 1) / 3, sv = (rows - 1) / 3;
    TColStd_Array1OfReal uk(1, su + 1), vk(1, sv + 1);
    TColStd_Array1OfInteger um(1, su + 1), vm(1, sv + 1);
    knots(su, uk, um);
    knots(sv, vk, vm);
    return new Geom_BSplineSurface(poles, uk, vk, um, vm, 3, 3);
}

const char* unitName(LengthUnit u) {
    switch (u) {
        case LengthUnit::Millimetre:
            return "MM";
        case LengthUnit::Centimetre:
            return "CM";
        case LengthUnit::Inch:
            return "INCH";
        case LengthUnit::Metre:
            break;
    }
    return "M";
}

}  // namespace occt
}  // namespace io
}  // namespace pw
