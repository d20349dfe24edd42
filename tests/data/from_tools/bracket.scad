// A CAD part for bracket.stl (make_files.sh): a plate with a boss, a through hole and two slots, as a machinist would
// draw it; OpenSCAD writes it as an ASCII STL of triangles, slivers included.
$fn = 48;
difference() {
  union() {
    cube([40, 24, 4]);
    translate([20, 12, 0]) cylinder(h = 12, r = 8);
  }
  translate([20, 12, -1]) cylinder(h = 14, r = 4);
  for (x = [6, 34]) translate([x - 1.5, 4, -1]) cube([3, 16, 6]);
}
