function text = parameter_text(parameter, value)
% A parameter's value as the C++ experts print it: a number as ostream
% writes it (6 significant digits), a flag as 1 or 0.
  switch parameter.kind
    case 'number'
      text = sprintf('%g', value);
    case 'whole'
      text = sprintf('%.0f', value);
    case 'flag'
      text = sprintf('%d', logical(value));
    otherwise
      text = value;
  end
end
