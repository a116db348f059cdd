function text = parameter_lines(parameters)
% One line per parameter: "  name (default D, RANGE): meaning".
  text = '';
  for i = 1:numel(parameters)
    p = parameters(i);
    text = [text sprintf('  %s (default %s, %s): %s\n', p.name, parameter_text(p, p.default), p.range, ...
                         p.meaning)]; %#ok<AGROW>
  end
end
