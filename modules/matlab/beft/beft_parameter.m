function expert = beft_parameter(expert, kind, name, default, varargin)
%BEFT_PARAMETER  Declares a named parameter (the C++ DeclaredParameters), set by --param NAME=VALUE.
%   expert = beft_parameter(expert, 'number', NAME, DEFAULT, LOW, HIGH, MEANING)
%   expert = beft_parameter(expert, 'number', NAME, DEFAULT, LOW, HIGH, MEANING, LOW_OPEN, HIGH_OPEN)
%   expert = beft_parameter(expert, 'whole',  NAME, DEFAULT, LOW, HIGH, MEANING)
%   expert = beft_parameter(expert, 'flag',   NAME, DEFAULT, MEANING)
%   expert = beft_parameter(expert, 'text',   NAME, DEFAULT, MEANING)
%   LOW or HIGH may be -Inf or Inf (no limit). fire gets the values as
%   parameters.NAME; --help and --interface print the declarations, in the
%   C++ experts' words.
  if any(strcmp({expert.parameters.name}, name))
    error('beft:parameter', 'parameter %s declared twice', name);
  end
  p = struct('name', name, 'kind', kind, 'default', default, 'value', default, 'low', -Inf, 'high', Inf, ...
             'low_open', false, 'high_open', false, 'range', '', 'meaning', '');
  switch kind
    case 'number'
      [p.low, p.high, p.meaning] = varargin{1:3};
      if numel(varargin) >= 5
        [p.low_open, p.high_open] = varargin{4:5};
      end
      p.default = double(default);
      p.range = number_range(p.low, p.high, p.low_open, p.high_open);
    case 'whole'
      [p.low, p.high, p.meaning] = varargin{1:3};
      p.default = double(default);
      p.range = sprintf('whole number in [%.0f, %.0f]', p.low, p.high);
    case 'flag'
      p.meaning = varargin{1};
      p.default = logical(default);
      p.range = '0|1';
    case 'text'
      p.meaning = varargin{1};
      p.range = 'text';
    otherwise
      error('beft:parameter', 'parameter %s: kind %s is not number, whole, flag or text', name, kind);
  end
  p.value = p.default;
  expert.parameters(end + 1) = p;
end

% The range as the C++ DeclaredParameters writes it ("[0, 1]", ">= 0", ...).
function text = number_range(low, high, low_open, high_open)
  brackets = '[]()';
  if isfinite(low) && isfinite(high)
    text = sprintf('%s%g, %g%s', brackets(1 + 2 * low_open), low, high, brackets(2 + 2 * high_open));
  elseif isfinite(low)
    text = sprintf('%s %g', choose(low_open, '>', '>='), low);
  elseif isfinite(high)
    text = sprintf('%s %g', choose(high_open, '<', '<='), high);
  else
    text = 'any finite number';
  end
end

function value = choose(condition, if_true, if_false)
  if condition
    value = if_true;
  else
    value = if_false;
  end
end
