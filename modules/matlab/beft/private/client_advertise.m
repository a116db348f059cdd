function text = client_advertise(topics, types)
% The client's advertise message: channel k is topics{k}, of beft type
% types{k}, all with encoding json.
  channels = cell(1, numel(topics));
  for k = 1:numel(topics)
    channels{k} = struct('id', k, 'topic', topics{k}, 'encoding', 'json', 'schemaName', types{k});
  end
  text = beft_json_encode(struct('op', 'advertise', 'channels', {channels}));
end
