function a = beft_azimuth(px, py, nose_heading_deg, ox, oy)
%BEFT_AZIMUTH  Azimuth of (ox, oy) seen from (px, py) relative to the nose [deg], (-180, 180], as lib/model.
  bearing = atan2(oy - py, ox - px) * (180.0 / pi);
  a = beft_wrap_degrees(bearing - nose_heading_deg);
end
