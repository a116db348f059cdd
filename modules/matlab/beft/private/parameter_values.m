function values = parameter_values(parameters)
% What fire gets: one field per parameter, its value.
  values = struct();
  for i = 1:numel(parameters)
    values.(parameters(i).name) = parameters(i).value;
  end
end
