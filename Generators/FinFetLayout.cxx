#include "FinFetLayout.h"

#include "FinFetGenerator.h"

namespace cgmesh
{
namespace
{

bool inside(double value, double low, double high)
{
  return value > low && value < high;
}

FinFetMaterial materialInside(double x, double y, double z)
{
  if (z < 20)
  {
    return Substrate;
  }
  if (z < 30)
  {
    return BuriedOxide;
  }
  const bool underGate = inside(x, 20, 40);
  const bool inSpacer = inside(x, 15, 20) || inside(x, 40, 45);
  if (inside(y, -5, 5) && z < 60)
  {
    return underGate ? FinChannel : (x < 30 ? Source : Drain);
  }
  const bool besideFin = inside(y, -7, 7) && z < 62;
  if (underGate)
  {
    return besideFin ? GateOxide : (inside(y, -11, 11) ? Gate : Isolation);
  }
  return inSpacer && inside(y, -11, 11) ? Spacer : Isolation;
}

} // namespace

const std::vector<double>& finFetBreaks(int axis)
{
  static const std::vector<double> breaks[3] = { { 0, 15, 20, 40, 45, 60 },
    { -17, -11, -7, -5, 5, 7, 11, 17 }, { 0, 20, 30, 60, 62, 72 } };
  return breaks[axis];
}

int finFetMaterialAt(double x, double y, double z)
{
  return materialInside(x, y, z);
}

} // namespace cgmesh
