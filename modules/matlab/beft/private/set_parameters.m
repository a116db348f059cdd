function parameters = set_parameters(parameters, given)
% Every parameter back to its default, then each --param NAME=VALUE of
% GIVEN set; an error (beft:parameter) names an unknown name, a value out
% of range or one that is not NAME=VALUE.
  for i = 1:numel(parameters)
    parameters(i).value = parameters(i).default;
  end
  for k = 1:numel(given)
    equals = strfind(given{k}, '=');
    if isempty(equals) || equals(1) == 1
      error('beft:parameter', '--param ''%s'' is not NAME=VALUE', given{k});
    end
    name = given{k}(1:equals(1) - 1);
    i = find(strcmp({parameters.name}, name), 1);
    if isempty(i)
      known = strjoin({parameters.name}, ', ');
      if isempty(known)
        known = 'none';
      end
      error('beft:parameter', 'unknown parameter ''%s'' (known: %s)', name, known);
    end
    [value, ok] = accept(parameters(i), given{k}(equals(1) + 1:end));
    if ~ok
      error('beft:parameter', 'parameter %s=''%s'' is not %s', name, given{k}(equals(1) + 1:end), ...
            parameters(i).range);
    end
    parameters(i).value = value;
  end
end

function [value, ok] = accept(p, text)
  value = [];
  switch p.kind
    case 'number'
      value = str2double(text);
      ok = isfinite(value) && above(value, p.low, p.low_open) && above(p.high, value, p.high_open);
    case 'whole'
      value = str2double(text);
      ok = ~isempty(regexp(text, '^[-+]?[0-9]+$', 'once')) && value >= p.low && value <= p.high;
    case 'flag'
      value = any(strcmp(text, {'1', 'true', 'yes', 'on'}));
      ok = value || any(strcmp(text, {'0', 'false', 'no', 'off'}));
    otherwise
      value = text;
      ok = true;
  end
end

function yes = above(a, b, strictly)
  if strictly
    yes = a > b;
  else
    yes = a >= b;
  end
end
