"""Probe: OCC Approx_CurveOnSurface's MaxError3d on C0 bicubic B-spline surfaces (kink at u = 1/2)."""
import math, random
import numpy as np
from gmpy2 import mpq
from exactcagd import BezierCurve, BSplineSurface
from exactcagd.refdata.exporters import to_occ
from OCP.OCP.Approx import Approx_CurveOnSurface
from OCP.OCP.Geom2dAdaptor import Geom2dAdaptor_Curve
from OCP.OCP.GeomAbs import GeomAbs_Shape
from OCP.OCP.GeomAdaptor import GeomAdaptor_Surface

rng = random.Random(1)
rows = []
for case in range(30):
    p = q = 3
    ku = [0] * 4 + [mpq(1, 2)] * 3 + [1] * 4  # C0 at u = 1/2
    kv = [0] * 4 + [1] * 4
    nu, nv = len(ku) - 4, 4
    net = [[[mpq(i, nu - 1), mpq(j, nv - 1), mpq(rng.randint(-16, 16), 16)] for j in range(nv)] for i in range(nu)]
    s = BSplineSurface(net, ku, kv)
    d = BezierCurve([[mpq(rng.randint(0, 8), 32), mpq(rng.randint(0, 32), 32)], [mpq(rng.randint(8, 24), 32), mpq(rng.randint(0, 32), 32)], [mpq(rng.randint(24, 32), 32), mpq(rng.randint(0, 32), 32)]])
    occ_s, occ_d = to_occ(s), to_occ(d)
    for tol, cont in ((1e-6, GeomAbs_Shape.GeomAbs_C1), (1e-6, GeomAbs_Shape.GeomAbs_C2), (1e-4, GeomAbs_Shape.GeomAbs_C1)):
        a = Approx_CurveOnSurface(Geom2dAdaptor_Curve(occ_d), GeomAdaptor_Surface(occ_s), 0.0, 1.0, tol)
        a.Perform(30, 14, cont, True, False)
        if not a.IsDone() or not a.HasResult():
            rows.append((case, tol, str(cont), "fail")); continue
        c = a.Curve3d()
        worst = 0.0
        for t in np.linspace(0, 1, 2001):
            u, v = d.evaluate(mpq(float(t)))
            e = s.evaluate(u, v)
            pt = c.Value(float(t))
            worst = max(worst, math.sqrt(float(sum((mpq(x) - y) ** 2 for x, y in zip((pt.X(), pt.Y(), pt.Z()), e)))))
        rows.append((case, tol, str(cont).split('.')[-1], worst, a.MaxError3d(), worst / a.MaxError3d() if a.MaxError3d() else math.inf))
under = [r for r in rows if len(r) > 4 and r[3] > r[4] and r[3] > 1e-13]
print(len(rows), "runs;", len(under), "under-estimates above 1e-13")
for r in sorted(under, key=lambda r: -r[5])[:8]:
    print(r)
print("max ratio", max(r[5] for r in rows if len(r) > 4))
