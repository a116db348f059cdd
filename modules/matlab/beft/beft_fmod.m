function r = beft_fmod(x, y)
%BEFT_FMOD  C's fmod(x, y) for finite scalars x and y > 0: x - n*y, n = trunc(x/y), exactly.
%   MATLAB's and Octave's rem and mod are not fmod: they return 0 when x/y
%   is within round-off of an integer, where fmod gives a value just under
%   y. fmod's result is always a double, so computed here without rounding:
%   n*y is exact while it stays below 2^53, x - n*y is exact (Sterbenz:
%   n*y is within a factor of two of x), and a quotient rounded to the next
%   integer is undone exactly.
  a = abs(x);
  n = fix(a / y);
  r = a - n * y;
  if r < 0
    r = r + y;
  elseif r >= y
    r = r - y;
  end
  if x < 0 || (x == 0 && 1 / x < 0)
    r = -r;  % fmod takes the sign of x
  end
end
