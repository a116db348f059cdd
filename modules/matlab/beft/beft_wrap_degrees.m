function a = beft_wrap_degrees(angle_deg)
%BEFT_WRAP_DEGREES  An angle wrapped into (-180, 180] degrees, as lib/model computes it.
  a = beft_fmod(angle_deg, 360.0);
  if a <= -180.0
    a = a + 360.0;
  end
  if a > 180.0
    a = a - 360.0;
  end
end
