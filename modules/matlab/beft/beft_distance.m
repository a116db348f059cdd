function d = beft_distance(px, py, pz, ox, oy, oz)
%BEFT_DISTANCE  3-D distance from (px, py, pz) to (ox, oy, oz), in lib/model's order of operations.
  d = sqrt((ox - px) * (ox - px) + (oy - py) * (oy - py) + (oz - pz) * (oz - pz));
end
