function message = announcement(expert, process_name, resume_log)
% The first message, on /beft/expert: who the expert is (the fields
% --interface prints).
  reads = arrayfun(@(p) struct('channel', p.channel, 'type', p.type), expert.inputs, 'UniformOutput', false);
  writes = arrayfun(@(p) struct('channel', p.channel, 'type', p.type), expert.outputs, 'UniformOutput', false);
  parameters = arrayfun(@(p) struct('name', p.name, 'kind', announced_kind(p.kind), ...
                                    'default', parameter_text(p, p.default), 'value', parameter_text(p, p.value), ...
                                    'range', p.range, 'meaning', p.meaning), ...
                        expert.parameters, 'UniformOutput', false);
  message = struct('protocol', 1, 'name', process_name, 'pid', javaMethod('pid', 'beft.Heartbeats'), ...
                   'host', char(javaMethod('hostName', 'beft.Heartbeats')), 'reads', {reads}, ...
                   'writes', {writes}, 'parameters', {parameters}, 'resume_log', resume_log);
end

% A flag is announced as the C++ experts' kind "bool".
function kind = announced_kind(kind)
  if strcmp(kind, 'flag')
    kind = 'bool';
  end
end
