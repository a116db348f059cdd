function s = subscribe_wanted(s)
% Subscribes to every wanted channel the server has advertised and that is
% not subscribed yet; subscription id k is s.subscribed{k}.
  requests = {};
  for i = 1:numel(s.wanted)
    topic = s.wanted{i};
    at = find(strcmp(s.server_topics, topic), 1, 'last');
    if ~isempty(at) && ~any(strcmp(s.subscribed, topic))
      s.subscribed{end + 1} = topic;
      if strcmp(topic, 'FIRE')
        s.socket.keepOnly(numel(s.subscribed), 'expert', s.name);  % the tokens of the others stay in Java
      end
      requests{end + 1} = struct('id', numel(s.subscribed), 'channelId', s.server_ids(at)); %#ok<AGROW>
    end
  end
  if ~isempty(requests)
    s.socket.sendText(beft_json_encode(struct('op', 'subscribe', 'subscriptions', {requests})));
  end
end
