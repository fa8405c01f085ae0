// A square punch 2 × 2 × 1 whose bottom edges are rounded with radius 0.25, its flat bottom
// at z = 0: groups top, sides, and contact (the bottom and the rounded edges).
SetFactory("OpenCASCADE");
Box(1) = {-1, -1, 0, 2, 2, 1};
e() = Curve In BoundingBox{-1.1, -1.1, -0.01, 1.1, 1.1, 0.01};
Fillet{1}{e()}{0.25}
eps = 1e-6;
Physical Volume("body") = Volume{:};
Physical Surface("top") = Surface In BoundingBox{-1-eps, -1-eps, 1-eps, 1+eps, 1+eps, 1+eps};
Physical Surface("contact") = Surface In BoundingBox{-1-eps, -1-eps, -eps, 1+eps, 1+eps, 0.25+eps};
s() = Surface In BoundingBox{-1-eps, -1-eps, 0.25-eps, -1+eps, 1+eps, 1+eps};
s() += Surface In BoundingBox{1-eps, -1-eps, 0.25-eps, 1+eps, 1+eps, 1+eps};
s() += Surface In BoundingBox{-1-eps, -1-eps, 0.25-eps, 1+eps, -1+eps, 1+eps};
s() += Surface In BoundingBox{-1-eps, 1-eps, 0.25-eps, 1+eps, 1+eps, 1+eps};
Physical Surface("sides") = s();
