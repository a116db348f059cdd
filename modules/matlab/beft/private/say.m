function say(process_name, format, varargin)
% A line on standard error, "[name] ...", as every process of a run writes.
  fprintf(2, ['[%s] ' format '\n'], process_name, varargin{:});
end
