import cvt2, matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection
from shapely.geometry import LineString, Polygon

room = Polygon([(0, 0), (4, 0), (4, 3), (0, 3)], holes=[[(1, 1), (2, 1), (2, 2), (1, 2)]])
wall = LineString([(2.5, 0), (3, 1.5), (3.5, 2.5)])  # an inner constraint: cells stop at it
domain = cvt2.Domain.from_shapely(room, constraints=[wall])
cells = cvt2.optimize(domain, cvt2.random_points(domain, 300)).bounded_voronoi()
fig, ax = plt.subplots(figsize=(6, 4.5))
ax.add_collection(PolyCollection([cells.vertices[r] for r in cells.regions], array=cells.areas, edgecolor="w"))
ax.plot(*wall.xy, "r", lw=2), ax.plot(*cells.points.T, "k.", ms=2), ax.autoscale(), ax.set_aspect("equal")
fig.savefig("python_example.png", dpi=100, bbox_inches="tight")
