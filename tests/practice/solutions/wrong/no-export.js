function degree(mesh, v) {
  return 3;
}
